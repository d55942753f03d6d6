#include "batch_octree.h"

#include <algorithm>
#include <array>

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

void BatchOcTree::applySorted(const std::vector<uint64_t>& codes, bool missesClearOccupied,
                              const std::function<bool(const Vec3&)>* clearAt) {
  if (codes.empty()) return;
  bool createdRoot = false;
  if (root == nullptr) {
    root = new octomap::OcTreeNode();
    ++tree_size;
    createdRoot = true;
  }
  clearAt_ = clearAt;
  descend(root, createdRoot, 0, codes.data(), codes.data() + codes.size(), missesClearOccupied);
  clearAt_ = nullptr;
}

bool BatchOcTree::missClears(uint64_t code) const {
  if (clearAt_ == nullptr) return false;
  const octomap::point3d c = keyToCoord(keyOfCode(code));
  return (*clearAt_)(Vec3(c.x(), c.y(), c.z()));
}

void BatchOcTree::descend(octomap::OcTreeNode* node, bool justCreated, unsigned depth,
                          const uint64_t* begin, const uint64_t* end, bool missesClearOccupied) {
  if (depth == tree_depth) {
    COINSPECT_ASSERT(end - begin == 1);  // the codes are unique per cell
    const bool wasOccupied = !justCreated && isNodeOccupied(node);
    const bool hit = (*begin & 1U) != 0;
    if (!hit && wasOccupied && !missesClearOccupied && !missClears(*begin)) return;
    updateNodeLogOdds(node, hit ? prob_hit_log : prob_miss_log);
    const bool isOccupied = isNodeOccupied(node);
    if (justCreated) ++known_;
    if (justCreated || isOccupied != wasOccupied) noteChanged(*begin);
    if (isOccupied != wasOccupied) {
      if (isOccupied)
        ++occupied_;
      else
        --occupied_;
    }
    return;
  }
  // A node without children that existed before would be a pruned leaf; this tree is never
  // pruned, so that cannot happen.
  COINSPECT_ASSERT(justCreated || nodeHasChildren(node));
  const unsigned shift = 3 * (tree_depth - 1 - depth) + 1;  // child index bits in a code
  const uint64_t* first = begin;
  while (first != end) {
    const unsigned child = static_cast<unsigned>((*first >> shift) & 7U);
    const uint64_t* last = first + 1;
    while (last != end && ((*last >> shift) & 7U) == child)
      ++last;
    bool created = false;
    if (!nodeChildExists(node, child)) {
      createNodeChild(node, child);
      created = true;
    }
    descend(getNodeChild(node, child), created, depth + 1, first, last, missesClearOccupied);
    first = last;
  }
  node->updateOccupancyChildren();
}

void BatchOcTree::noteChanged(uint64_t code) {
  const octomap::OcTreeKey key = keyOfCode(code);
  for (int i = 0; i < 3; ++i) {
    changed_.low[i] = std::min(changed_.low[i], static_cast<int>(key[i]));
    changed_.high[i] = std::max(changed_.high[i], static_cast<int>(key[i]));
  }
}

BatchOcTree::KeyBox BatchOcTree::takeChangedKeys() {
  const KeyBox box = changed_;
  changed_ = KeyBox{};
  return box;
}

void BatchOcTree::appendLeafCodes(std::vector<uint64_t>& codes) const {
  if (root != nullptr) appendLeafCodes(root, 0, 0, codes);
}

void BatchOcTree::appendLeafCodes(const octomap::OcTreeNode* node, unsigned depth, uint64_t morton,
                                  std::vector<uint64_t>& codes) const {
  if (depth == tree_depth) {
    codes.push_back((morton << 1) | (isNodeOccupied(node) ? 1U : 0U));
    return;
  }
  COINSPECT_ASSERT(nodeHasChildren(node));  // never pruned
  for (unsigned child = 0; child < 8; ++child)
    if (nodeChildExists(node, child))
      appendLeafCodes(getNodeChild(node, child), depth + 1, (morton << 3) | child, codes);
}

}  // namespace coinspect::mapping
