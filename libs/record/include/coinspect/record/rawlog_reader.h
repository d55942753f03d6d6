// RawlogReader: reads a coinspect rawlog back one observation at a time (constant memory).
// A truncated or corrupted file is read up to the damage; then next() returns false and
// status() says how many objects were read and at which byte offset the damage starts. Damage
// includes a readable object with an impossible timestamp: earlier than the object before it
// (the writer writes in time order) or later than setLatestTime's bound.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "coinspect/record/run_header.h"

namespace mrpt::obs {
class CObservation;
}

namespace coinspect::record {
namespace detail {
class GzipInput;
}

struct ReadStatus {
  bool clean = true;     // false once damage was found
  uint64_t objects = 0;  // objects read successfully, header comment included
  // Where the first unreadable object starts, in bytes of the DECOMPRESSED stream (the
  // serialized objects; the gzip layer has no object boundaries). compressedOffset is how far
  // zlib had consumed the file when the damage was found.
  uint64_t offset = 0;
  uint64_t compressedOffset = 0;
  std::string message;  // "" when clean, else "<file>: N objects read, damage at byte offset X ..."
};

class RawlogReader {
 public:
  // Opens `path` and reads the header comment. Throws InputError if the file cannot be opened or
  // does not start with a coinspect run header.
  explicit RawlogReader(const std::filesystem::path& path);
  ~RawlogReader();
  RawlogReader(const RawlogReader&) = delete;
  RawlogReader& operator=(const RawlogReader&) = delete;

  const RunHeader& header() const { return header_; }

  // The next observation after the header; false at the end of the file or at damage (then
  // status().clean is false). Never throws for damaged content.
  bool next(std::shared_ptr<mrpt::obs::CObservation>& observation);

  const ReadStatus& status() const { return status_; }

  // The latest mission time (s) an object of this run can carry (the caller knows it from the
  // recorded config: start_timeout + budget, and a margin); later ones are damage. Without it,
  // any finite time in order is accepted.
  void setLatestTime(double seconds) { latestTime_ = seconds; }

 private:
  std::shared_ptr<mrpt::obs::CObservation> readObject();
  void markDamaged(uint64_t offset, const std::string& why);
  // "" when `time` may follow the objects read so far (and then it becomes the previous time).
  std::string timestampFault(double time);

  std::filesystem::path path_;
  std::unique_ptr<detail::GzipInput> in_;
  RunHeader header_;
  ReadStatus status_;
  bool finished_ = false;
  double latestTime_;
  double previousTime_ = 0.0;
};

}  // namespace coinspect::record
