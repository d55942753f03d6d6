#include "coinspect/comms/link_matrix.h"

#include "coinspect/core/error.h"

namespace coinspect::comms {

LinkMatrix::LinkMatrix(size_t units) : units_(units), cells_(units * units, 0) {}

bool LinkMatrix::linked(uint32_t i, uint32_t j) const {
  COINSPECT_ASSERT(i < units_ && j < units_);
  return cells_[i * units_ + j] != 0;
}

void LinkMatrix::setLinked(uint32_t i, uint32_t j, bool value) {
  COINSPECT_ASSERT(i < units_ && j < units_);
  COINSPECT_ASSERT(i != j || !value);
  cells_[i * units_ + j] = value ? 1 : 0;
  cells_[j * units_ + i] = value ? 1 : 0;
}

void LinkMatrix::clear() {
  cells_.assign(cells_.size(), 0);
}

std::vector<uint32_t> LinkMatrix::neighbours(uint32_t unit) const {
  COINSPECT_ASSERT(unit < units_);
  std::vector<uint32_t> result;
  const uint8_t* row = cells_.data() + unit * units_;
  for (uint32_t j = 0; j < units_; ++j)
    if (row[j] != 0) result.push_back(j);
  return result;
}

size_t LinkMatrix::linkCount() const {
  size_t count = 0;
  for (size_t i = 0; i < units_; ++i)
    for (size_t j = i + 1; j < units_; ++j)
      count += cells_[i * units_ + j];
  return count;
}

std::vector<LinkChange> LinkMatrix::changedSince(const LinkMatrix& before) const {
  COINSPECT_ASSERT(before.units_ == units_);
  std::vector<LinkChange> changes;
  for (size_t i = 0; i < units_; ++i)
    for (size_t j = i + 1; j < units_; ++j) {
      const size_t cell = i * units_ + j;
      if (cells_[cell] != before.cells_[cell])
        changes.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(j), cells_[cell] != 0});
    }
  return changes;
}

}  // namespace coinspect::comms
