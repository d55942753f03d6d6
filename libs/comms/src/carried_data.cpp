#include "coinspect/comms/carried_data.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::comms {

CarriedData::CarriedData(size_t units, size_t items)
    : units_(units), items_(items), held_(units * items, 0), counts_(units, 0) {}

bool CarriedData::holds(uint32_t unit, uint32_t item) const {
  COINSPECT_ASSERT(unit < units_ && item < items_);
  return held_[unit * items_ + item] != 0;
}

size_t CarriedData::heldCount(uint32_t unit) const {
  COINSPECT_ASSERT(unit < units_);
  return counts_[unit];
}

bool CarriedData::add(uint32_t unit, uint32_t item) {
  COINSPECT_ASSERT(unit < units_ && item < items_);
  auto& cell = held_[unit * items_ + item];
  if (cell) return false;
  cell = 1;
  ++counts_[unit];
  return true;
}

void CarriedData::drop(uint32_t unit) {
  COINSPECT_ASSERT(unit < units_);
  std::fill(held_.begin() + static_cast<long>(unit * items_),
            held_.begin() + static_cast<long>((unit + 1) * items_), uint8_t{0});
  counts_[unit] = 0;
}

std::vector<Handover> CarriedData::exchange(const LinkMatrix& links,
                                            const std::vector<bool>& alive) {
  COINSPECT_ASSERT(links.size() == units_ && alive.size() == units_);
  std::vector<Handover> out;
  const std::vector<uint8_t> before = held_;
  for (uint32_t u = 0; u < units_; ++u) {
    if (!alive[u] || counts_[u] == items_) continue;
    for (const uint32_t n : links.neighbours(u)) {
      if (!alive[n]) continue;
      const uint8_t* theirs = before.data() + n * items_;
      for (uint32_t item = 0; item < items_; ++item) {
        if (!theirs[item] || held_[u * items_ + item]) continue;
        held_[u * items_ + item] = 1;
        ++counts_[u];
        out.push_back({u, item, n});
      }
    }
  }
  // By receiver, then item: neighbours were visited in index order, so sort the items of each.
  std::stable_sort(out.begin(), out.end(), [](const Handover& a, const Handover& b) {
    return a.unit != b.unit ? a.unit < b.unit : a.item < b.item;
  });
  return out;
}

MeetingCounter::MeetingCounter(size_t units, double gap)
    : units_(units),
      gap_(gap),
      previous_(units),
      lostSince_(units * units, -std::numeric_limits<double>::infinity()) {
  if (!(gap >= 0.0) || !std::isfinite(gap))
    throw InputError("meetings", "gap", "must be a finite time >= 0 s");
}

std::vector<std::pair<uint32_t, uint32_t>> MeetingCounter::update(double time,
                                                                  const LinkMatrix& links) {
  COINSPECT_ASSERT(links.size() == units_);
  std::vector<std::pair<uint32_t, uint32_t>> meetings;
  for (const auto& change : links.changedSince(previous_)) {
    double& lost = lostSince_[change.a * units_ + change.b];
    if (!change.linked)
      lost = time;
    else if (!first_ && time - lost >= gap_)
      meetings.emplace_back(change.a, change.b);
  }
  previous_ = links;
  first_ = false;
  return meetings;
}

}  // namespace coinspect::comms
