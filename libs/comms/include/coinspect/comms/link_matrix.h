// Who is linked to whom at one moment: a symmetric N x N table of booleans.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace coinspect::comms {

// One pair whose link state differs between two matrices; a < b.
struct LinkChange {
  uint32_t a = 0;
  uint32_t b = 0;
  bool linked = false;  // the state in the newer matrix
  bool operator==(const LinkChange& other) const {
    return a == other.a && b == other.b && linked == other.linked;
  }
};

// Symmetric by construction (setLinked writes both halves); a unit is never linked to itself.
// Copyable value type.
class LinkMatrix {
 public:
  LinkMatrix() = default;
  explicit LinkMatrix(size_t units);

  size_t size() const { return units_; }
  bool linked(uint32_t i, uint32_t j) const;
  void setLinked(uint32_t i, uint32_t j, bool value);
  // Clears every link, keeping the size.
  void clear();

  // Units linked to `unit`, in increasing index order.
  std::vector<uint32_t> neighbours(uint32_t unit) const;
  // Number of linked unordered pairs.
  size_t linkCount() const;
  // Pairs (a < b, row-major order) whose state differs from `before`, with the new state.
  // Both matrices must have the same size.
  std::vector<LinkChange> changedSince(const LinkMatrix& before) const;

  bool operator==(const LinkMatrix& other) const {
    return units_ == other.units_ && cells_ == other.cells_;
  }
  bool operator!=(const LinkMatrix& other) const { return !(*this == other); }

 private:
  size_t units_ = 0;
  std::vector<uint8_t> cells_;  // row-major, units_ * units_
};

}  // namespace coinspect::comms
