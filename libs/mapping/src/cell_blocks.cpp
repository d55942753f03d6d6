#include "cell_blocks.h"

#include <octomap/OcTree.h>

#include <algorithm>

#include "coinspect/core/error.h"

namespace coinspect::mapping {

void sortUniqueCodes(std::vector<uint64_t>& codes, std::vector<uint64_t>& buffer) {
  // Codes have 49 significant bits (48 of Morton code + the occupied flag). A scan's cells share
  // the high bits (they lie within a few hundred metres), so most high digits are constant and
  // their passes are skipped; radix sort measured several times faster than std::sort here.
  constexpr int kDigitBits = 11;
  constexpr size_t kBuckets = size_t{1} << kDigitBits;
  constexpr int kPasses = (49 + kDigitBits - 1) / kDigitBits;
  const size_t n = codes.size();
  buffer.resize(n);
  std::array<size_t, kBuckets> count{};
  for (int pass = 0; pass < kPasses; ++pass) {
    const int shift = pass * kDigitBits;
    count.fill(0);
    for (const uint64_t c : codes)
      ++count[(c >> shift) & (kBuckets - 1)];
    if (n == 0 || count[(codes[0] >> shift) & (kBuckets - 1)] == n) continue;
    size_t sum = 0;
    for (auto& bucket : count) {
      const size_t here = bucket;
      bucket = sum;
      sum += here;
    }
    for (const uint64_t c : codes)
      buffer[count[(c >> shift) & (kBuckets - 1)]++] = c;
    codes.swap(buffer);
  }
  // Sorted ascending, so the occupied code of a cell (flag 1) comes last among its cell's codes.
  size_t out = 0;
  for (size_t i = 0; i < n; ++i) {
    if (i + 1 < n && (codes[i + 1] >> 1) == (codes[i] >> 1)) continue;
    codes[out++] = codes[i];
  }
  codes.resize(out);
}

CellFrame::CellFrame(double res) : resolution(res), factor(1.0 / res) {
  // OctoMap's defaults (hit 0.7, miss 0.4, clamping 0.1192-0.971, occupied at 0.5) as its own
  // logodds() rounds them to float; one tree is made once for them (each tree reserves a 600 KB
  // ray buffer, which a map no longer needs).
  static const octomap::OcTree model(0.5);
  hitLog = model.getProbHitLog();
  missLog = model.getProbMissLog();
  clampMinLog = model.getClampingThresMinLog();
  clampMaxLog = model.getClampingThresMaxLog();
  occupiedLog = model.getOccupancyThresLog();
}

CellBlocks::Block& CellBlocks::blockFor(uint64_t blockMorton) {
  const auto [it, inserted] =
      index_.try_emplace(blockMorton, static_cast<uint32_t>(blocks_.size()));
  if (inserted) {
    auto block = std::make_unique<Block>();
    block->logOdds.fill(kUnknown);
    block->low = keyOfMorton(blockMorton << (3 * kBlockBits));
    blocks_.push_back(std::move(block));
  }
  return *blocks_[it->second];
}

const CellBlocks::Block* CellBlocks::blockOf(uint64_t morton) const {
  const auto it = index_.find(morton >> (3 * kBlockBits));
  return it == index_.end() ? nullptr : blocks_[it->second].get();
}

float CellBlocks::logOdds(const CellKey& key) const {
  const uint64_t morton = mortonOf(key);
  const Block* block = blockOf(morton);
  return block == nullptr ? kUnknown : block->logOdds[morton & (kBlockCells - 1)];
}

void CellBlocks::applySorted(const std::vector<uint64_t>& codes, bool missesClearOccupied,
                             const std::function<bool(const Vec3&)>* clearAt) {
  constexpr unsigned kCellShift = 1 + 3 * kBlockBits;  // the block's bits in a code
  const uint64_t* code = codes.data();
  const uint64_t* const end = code + codes.size();
  while (code != end) {
    const uint64_t blockCodes = *code >> kCellShift;
    Block& block = blockFor(blockCodes);
    for (; code != end && (*code >> kCellShift) == blockCodes; ++code) {
      float& value = block.logOdds[(*code >> 1) & (kBlockCells - 1)];
      const bool justCreated = value == kUnknown;
      const bool wasOccupied = !justCreated && frame_.occupied(value);
      const bool hit = (*code & 1U) != 0;
      if (!hit && wasOccupied && !missesClearOccupied &&
          !(clearAt != nullptr &&
            (*clearAt)(frame_.floatCentreOf(keyOfMorton(*code >> 1)).cast<double>())))
        continue;
      // OctoMap's updateNodeLogOdds on a node created at 0.
      if (justCreated) value = 0.0f;
      value += hit ? frame_.hitLog : frame_.missLog;
      if (value < frame_.clampMinLog)
        value = frame_.clampMinLog;
      else if (value > frame_.clampMaxLog)
        value = frame_.clampMaxLog;
      const bool isOccupied = frame_.occupied(value);
      if (justCreated) {
        ++known_;
        ++block.known;
      }
      if (justCreated || isOccupied != wasOccupied) noteChanged(*code);
      if (isOccupied != wasOccupied) {
        if (isOccupied) {
          ++occupied_;
          ++block.occupied;
        } else {
          --occupied_;
          --block.occupied;
        }
      }
    }
  }
}

void CellBlocks::appendCodes(std::vector<uint64_t>& codes) const {
  for (const auto& block : blocks_) {
    const uint64_t base = mortonOf(block->low);
    for (unsigned i = 0; i < kBlockCells; ++i) {
      const float value = block->logOdds[i];
      if (value != kUnknown)
        codes.push_back(((base | i) << 1) | (frame_.occupied(value) ? 1U : 0U));
    }
  }
}

void CellBlocks::noteChanged(uint64_t code) {
  const CellKey key = keyOfMorton(code >> 1);
  for (int i = 0; i < 3; ++i) {
    changed_.low[i] = std::min(changed_.low[i], static_cast<int>(key[i]));
    changed_.high[i] = std::max(changed_.high[i], static_cast<int>(key[i]));
  }
}

CellBlocks::KeyBox CellBlocks::takeChangedKeys() {
  const KeyBox box = changed_;
  changed_ = KeyBox{};
  return box;
}

}  // namespace coinspect::mapping
