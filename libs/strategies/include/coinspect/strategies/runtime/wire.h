// Byte encoding of strategy messages: little-endian fixed-size fields, length-prefixed lists.
// A reader never throws on hostile input: it reports a truncated or oversized message as
// failure, and the caller drops the message.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::strategies::runtime {

class WireWriter {
 public:
  void u8(uint8_t v) { bytes_.push_back(v); }
  void u32(uint32_t v) { raw(&v, sizeof v); }
  void i32(int32_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void vec3(const agent::Vec3& v) {
    f64(v.x());
    f64(v.y());
    f64(v.z());
  }
  std::vector<uint8_t> take() { return std::move(bytes_); }

 private:
  void raw(const void* data, size_t size) {
    const auto* p = static_cast<const uint8_t*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  std::vector<uint8_t> bytes_;
};

class WireReader {
 public:
  explicit WireReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  bool u8(uint8_t* v) { return raw(v, sizeof *v); }
  bool u32(uint32_t* v) { return raw(v, sizeof *v); }
  bool i32(int32_t* v) { return raw(v, sizeof *v); }
  bool f64(double* v) { return raw(v, sizeof *v); }
  bool vec3(agent::Vec3* v) { return f64(&v->x()) && f64(&v->y()) && f64(&v->z()); }
  // A list length no larger than the bytes left could hold at `minItemBytes` each.
  bool count(uint32_t* n, size_t minItemBytes) {
    return u32(n) && static_cast<size_t>(*n) * minItemBytes <= bytes_.size() - at_;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  bool raw(void* out, size_t size) {
    if (bytes_.size() - at_ < size) return false;
    std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
    return true;
  }
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0;
};

}  // namespace coinspect::strategies::runtime
