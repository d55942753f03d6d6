#include "coinspect/strategies/slei/fleet_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_set>

#include "coinspect/planning/slei_schedule.h"
#include "coinspect/strategies/runtime/box_geometry.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kGroundCell = 0.5;     // m, the station's ground grid
constexpr double kGroundMargin = 15.0;  // m around the boxes that the grid covers

double horizontal(const Vec3& a, const Vec3& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// p is horizontally within `margin` of some box's footprint (any height).
bool nearAFootprint(const std::vector<agent::BoxView>& boxes, const Vec3& p, double margin) {
  return std::any_of(boxes.begin(), boxes.end(), [&](const agent::BoxView& box) {
    const Vec3 local = box.rotation.transpose() * (p - box.center);
    return std::abs(local.x()) < 0.5 * box.size.x() + margin &&
           std::abs(local.y()) < 0.5 * box.size.y() + margin;
  });
}

}  // namespace

std::vector<size_t> inspectorsPerSubgroup(size_t inspectors, size_t explorers, bool even,
                                          const std::vector<double>& weights) {
  std::vector<size_t> out(explorers, 0);
  if (explorers == 0) return out;
  double total = 0.0;
  for (const double w : weights)
    total += std::max(0.0, w);
  if (even || weights.size() != explorers || !(total > 0.0)) {
    for (size_t i = 0; i < explorers; ++i)
      out[i] = inspectors / explorers + (i < inspectors % explorers ? 1 : 0);
    return out;
  }
  std::vector<double> fraction(explorers);
  size_t given = 0;
  for (size_t i = 0; i < explorers; ++i) {
    const double share = static_cast<double>(inspectors) * std::max(0.0, weights[i]) / total;
    out[i] = static_cast<size_t>(std::floor(share));
    fraction[i] = share - static_cast<double>(out[i]);
    given += out[i];
  }
  std::vector<size_t> order(explorers);
  for (size_t i = 0; i < explorers; ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return fraction[a] > fraction[b]; });
  for (size_t k = 0; given < inspectors; ++k, ++given)
    ++out[order[k % explorers]];
  return out;
}

int32_t nearestFreeBox(const std::vector<agent::BoxView>& boxes,
                       const std::vector<uint8_t>& assigned, const Vec3& from) {
  // High-priority boxes first (urgent areas), then the others.
  for (const bool urgentOnly : {true, false}) {
    int32_t best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < boxes.size(); ++i) {
      if ((i < assigned.size() && assigned[i]) || (urgentOnly && !boxes[i].highPriority)) continue;
      const double d = horizontal(boxes[i].center, from);
      if (d < bestDistance) bestDistance = d, best = static_cast<int32_t>(i);
    }
    if (best >= 0) return best;
  }
  return -1;
}

agent::BoxView workspaceBox(const std::vector<agent::BoxView>& boxes) {
  agent::BoxView out;
  if (boxes.empty()) return out;
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const auto& box : boxes) {
    const auto bounds = runtime::boxBounds(box);
    low = low.cwiseMin(bounds.min);
    high = high.cwiseMax(bounds.max);
  }
  out.center = 0.5 * (low + high);
  out.size = high - low;
  return out;
}

std::vector<agent::BoxView> splitWorkspace(const agent::BoxView& workspace, size_t parts) {
  std::vector<agent::BoxView> out;
  const int axis = workspace.size.x() >= workspace.size.y() ? 0 : 1;
  const double width = workspace.size[axis] / static_cast<double>(std::max<size_t>(parts, 1));
  for (size_t i = 0; i < parts; ++i) {
    agent::BoxView slab = workspace;
    slab.size[axis] = width;
    slab.center[axis] = workspace.center[axis] - 0.5 * workspace.size[axis] +
                        (static_cast<double>(i) + 0.5) * width;
    out.push_back(slab);
  }
  return out;
}

std::vector<agent::BoxView> octreeChildren(const agent::BoxView& box, double maxEdge,
                                           bool splitHeight) {
  const auto bounds = runtime::boxBounds(box);
  const Vec3 size = bounds.max - bounds.min;
  Eigen::Vector3i halves = Eigen::Vector3i::Ones();
  for (int a = 0; a < (splitHeight ? 3 : 2); ++a)
    if (size[a] > maxEdge) halves[a] = 2;
  if (halves.prod() == 1) return {};
  std::vector<agent::BoxView> out;
  const Vec3 part = size.cwiseQuotient(halves.cast<double>());
  for (int z = 0; z < halves.z(); ++z)
    for (int y = 0; y < halves.y(); ++y)
      for (int x = 0; x < halves.x(); ++x) {
        agent::BoxView child;
        child.size = part;
        child.center = bounds.min + (Vec3(x, y, z) + Vec3::Constant(0.5)).cwiseProduct(part);
        child.highPriority = box.highPriority;
        out.push_back(child);
      }
  return out;
}

std::vector<std::vector<int32_t>> fixedBoxOrders(const std::vector<agent::BoxView>& boxes,
                                                 const std::vector<int32_t>& firstBoxes,
                                                 const std::vector<uint8_t>& taken) {
  std::vector<uint8_t> assigned(boxes.size(), 0);
  for (size_t i = 0; i < taken.size() && i < assigned.size(); ++i)
    assigned[i] = taken[i];
  std::vector<int32_t> last = firstBoxes;
  for (const int32_t b : firstBoxes)
    if (b >= 0) assigned[static_cast<size_t>(b)] = 1;
  std::vector<std::vector<int32_t>> orders(firstBoxes.size());
  for (bool dealt = true; dealt;) {
    dealt = false;
    for (size_t s = 0; s < last.size(); ++s) {
      if (last[s] < 0) continue;  // a subgroup without a box gets none later either
      const int32_t next =
          nearestFreeBox(boxes, assigned, boxes[static_cast<size_t>(last[s])].center);
      if (next < 0) return orders;
      assigned[static_cast<size_t>(next)] = 1;
      orders[s].push_back(next);
      last[s] = next;
      dealt = true;
    }
  }
  return orders;
}

void giveBoxToShortestOrder(std::vector<std::vector<int32_t>>& orders, size_t lost, int32_t box) {
  std::vector<int32_t>* shortest = nullptr;
  for (size_t i = 0; i < orders.size(); ++i)
    if (i != lost && (!shortest || orders[i].size() < shortest->size())) shortest = &orders[i];
  if (shortest) shortest->push_back(box);
}

Vec3 boxCorner(const agent::BoxView& box, double offset, double z, const Vec3& from) {
  const auto bounds = runtime::boxBounds(box);
  const Vec3 grow(offset, offset, 0.0);
  planning::MeetingCornerOptions options;
  options.inset = 0.0;
  options.height = z;
  return planning::nearestMeetingCorner(bounds.min - grow, bounds.max + grow, from, options).point;
}

Vec3 boxCorner(const std::vector<agent::BoxView>& boxes, size_t index, double offset, double z,
               const Vec3& from) {
  const auto outside = [&](const Vec3& p) { return !nearAFootprint(boxes, p, 0.0); };
  const Vec3 nearest = boxCorner(boxes[index], offset, z, from);
  if (outside(nearest)) return nearest;
  const auto bounds = runtime::boxBounds(boxes[index]);
  Vec3 best = nearest;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const double x : {bounds.min.x() - offset, bounds.max.x() + offset})
    for (const double y : {bounds.min.y() - offset, bounds.max.y() + offset}) {
      const Vec3 corner(x, y, z);
      const double d = std::hypot(x - from.x(), y - from.y());
      if (outside(corner) && d < bestDistance) bestDistance = d, best = corner;
    }
  return best;
}

Vec3 awayFromBox(const agent::BoxView& box, const Vec3& corner, double distance, double z) {
  Vec3 out(corner.x() - box.center.x(), corner.y() - box.center.y(), 0.0);
  const double norm = out.norm();
  out = norm > 1e-9 ? Vec3(out / norm) : Vec3::UnitX();
  return Vec3(corner.x(), corner.y(), z) + distance * out;
}

Vec3 waitPointOffCorner(const std::vector<agent::BoxView>& boxes, size_t index, const Vec3& corner,
                        size_t k, double spacing, double z) {
  constexpr double kFirstRow = 3.0;     // m out from the corner
  constexpr double kBoxClear = 1.5;     // m from every box's footprint
  constexpr int kRows = 8, kSides = 5;  // lattice extent: rows out, columns either side
  const Vec3 base = awayFromBox(boxes[index], corner, kFirstRow, z);
  const Vec3 out = (base - Vec3(corner.x(), corner.y(), z)).normalized();
  const Vec3 across(-out.y(), out.x(), 0.0);
  const auto clear = [&](const Vec3& p) { return !nearAFootprint(boxes, p, kBoxClear); };
  struct Candidate {
    double distance;
    int row, column;
    Vec3 point;
  };
  std::vector<Candidate> candidates;
  for (int row = 0; row < kRows; ++row)
    for (int column = -kSides; column < kSides; ++column) {
      const Vec3 p = base + spacing * (row * out + (column + 0.5) * across);
      candidates.push_back({(p - Vec3(corner.x(), corner.y(), z)).norm(), row, column, p});
    }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::tie(a.distance, a.row, a.column) < std::tie(b.distance, b.row, b.column);
  });
  size_t seen = 0;
  for (const auto& c : candidates)
    if (clear(c.point) && seen++ == k) return c.point;
  // Boxes all around: the lattice's k-th point, clear or not.
  return candidates[std::min(k, candidates.size() - 1)].point;
}

Vec3 relayWaitPoint(const Vec3& relay, size_t index, size_t count, double radius, double minChord,
                    double ringGap) {
  // Points on a circle of radius r with chords of at least minChord: 2 pi / (2 asin(c / 2r)).
  size_t first = 0;
  for (double r = radius;; r += ringGap) {
    const double ratio = std::min(1.0, minChord / (2.0 * r));
    const auto fits =
        std::max<size_t>(1, static_cast<size_t>(std::floor(M_PI / std::asin(ratio) + 1e-9)));
    const size_t on = std::min(fits, count - first);
    if (index < first + on) {
      const double angle =
          2.0 * M_PI * static_cast<double>(index - first) / static_cast<double>(on);
      return relay + Vec3(r * std::cos(angle), r * std::sin(angle), 0.0);
    }
    first += on;
  }
}

std::vector<StationShare> stationShares(const std::vector<agent::FleetMember>& fleet,
                                        const std::vector<agent::BoxView>& boxes) {
  std::vector<uint32_t> stations, explorers, inspectors;
  for (size_t i = 0; i < fleet.size(); ++i) {
    const auto unit = static_cast<uint32_t>(i);
    if (fleet[i].role == agent::Role::GroundStation) stations.push_back(unit);
    if (fleet[i].role == agent::Role::Explorer) explorers.push_back(unit);
    if (fleet[i].role == agent::Role::Photographer) inspectors.push_back(unit);
  }
  std::vector<StationShare> shares(stations.size());
  if (shares.empty()) return shares;
  const auto explorerCounts = inspectorsPerSubgroup(explorers.size(), shares.size(), true);
  std::vector<double> weights(explorerCounts.begin(), explorerCounts.end());
  const auto inspectorCounts =
      inspectorsPerSubgroup(inspectors.size(), shares.size(), false, weights);
  size_t nextExplorer = 0, nextInspector = 0;
  for (size_t k = 0; k < shares.size(); ++k) {
    shares[k].station = stations[k];
    shares[k].boxes.assign(boxes.size(), 0);
    for (size_t j = 0; j < explorerCounts[k]; ++j) {
      shares[k].explorerRanges.push_back(fleet[explorers[nextExplorer]].detectRange);
      shares[k].explorers.push_back(explorers[nextExplorer++]);
    }
    for (size_t j = 0; j < inspectorCounts[k]; ++j)
      shares[k].inspectors.push_back(inspectors[nextInspector++]);
  }
  // The boxes in strips: ordered along the longer spread of their centres.
  std::vector<size_t> order(boxes.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  double volume = 0.0;
  for (const auto& box : boxes) {
    low = low.cwiseMin(box.center);
    high = high.cwiseMax(box.center);
    volume += box.size.prod();
  }
  const int axis = boxes.empty() || high.x() - low.x() >= high.y() - low.y() ? 0 : 1;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return boxes[a].center[axis] < boxes[b].center[axis];
  });
  const double totalExplorers = static_cast<double>(std::max<size_t>(1, explorers.size()));
  double before = 0.0;
  for (const size_t b : order) {
    const double middle = (before + 0.5 * boxes[b].size.prod()) / std::max(volume, 1e-12);
    before += boxes[b].size.prod();
    // The station whose share of the volume (its share of the explorers) holds the middle; the
    // last one with explorers past the end (rounding).
    double upTo = 0.0;
    size_t owner = shares.size();
    for (size_t k = 0; k < shares.size(); ++k) {
      if (explorerCounts[k] == 0) continue;
      owner = k;
      upTo += static_cast<double>(explorerCounts[k]) / totalExplorers;
      if (middle < upTo) break;
    }
    if (owner == shares.size()) owner = 0;  // no explorer at all: the first station's
    shares[owner].boxes[b] = 1;
  }
  return shares;
}

namespace {

// Heterogeneous explorers: the subgroups' boxes dealt again, the largest to the longest range.
// Nothing changes when every range is the same.
void dealBoxesByRange(std::vector<Subgroup>& subgroups, const std::vector<double>& ranges,
                      const std::vector<agent::BoxView>& boxes) {
  if (ranges.size() != subgroups.size() ||
      std::all_of(ranges.begin(), ranges.end(), [&](double r) { return r == ranges.front(); }))
    return;
  std::vector<size_t> byRange;
  std::vector<int32_t> chosen;
  for (size_t i = 0; i < subgroups.size(); ++i) {
    byRange.push_back(i);
    if (subgroups[i].box >= 0) chosen.push_back(subgroups[i].box);
  }
  std::stable_sort(byRange.begin(), byRange.end(),
                   [&](size_t a, size_t b) { return ranges[a] > ranges[b]; });
  const auto volume = [&](int32_t b) { return boxes[static_cast<size_t>(b)].size.prod(); };
  std::stable_sort(chosen.begin(), chosen.end(),
                   [&](int32_t a, int32_t b) { return volume(a) > volume(b); });
  for (size_t k = 0; k < byRange.size(); ++k)
    subgroups[byRange[k]].box = k < chosen.size() ? chosen[k] : -1;
}

}  // namespace

FleetPlan makeFleetPlan(const StationShare& share, const std::vector<agent::BoxView>& boxes,
                        const Vec3& station, double groundZ, double now,
                        const PlanOptions& options) {
  const auto& explorers = share.explorers;
  const auto& inspectors = share.inspectors;
  FleetPlan plan;
  // Another station's boxes are not this one's to hand out.
  std::vector<uint8_t> assigned(boxes.size(), 1);
  for (size_t i = 0; i < share.boxes.size() && i < assigned.size(); ++i)
    assigned[i] = share.boxes[i] ? 0 : 1;
  Vec3 previousBox = station;
  for (const uint32_t explorer : explorers) {
    Subgroup s;
    s.explorer = explorer;
    s.station = share.station;
    s.box = nearestFreeBox(boxes, assigned, previousBox);
    if (s.box >= 0) {
      assigned[static_cast<size_t>(s.box)] = 1;
      previousBox = boxes[static_cast<size_t>(s.box)].center;
    }
    plan.subgroups.push_back(s);
  }
  dealBoxesByRange(plan.subgroups, share.explorerRanges, boxes);
  std::vector<double> weights;
  for (const auto& s : plan.subgroups) {
    const auto& size = s.box >= 0 ? boxes[static_cast<size_t>(s.box)].size : Vec3::Zero().eval();
    weights.push_back(size.prod());
  }
  const auto counts =
      inspectorsPerSubgroup(inspectors.size(), explorers.size(), options.evenSplit, weights);
  size_t next = 0;
  for (size_t k = 0; k < plan.subgroups.size(); ++k)
    for (size_t j = 0; j < counts[k]; ++j)
      plan.subgroups[k].inspectors.push_back(inspectors[next++]);
  // The station's first round: from where it stands, each subgroup's nearest corner in turn.
  Vec3 at = station;
  double time = now + options.firstMeetingLead;
  for (auto& s : plan.subgroups) {
    if (s.box < 0) continue;
    const Vec3 corner =
        boxCorner(boxes, static_cast<size_t>(s.box), options.cornerOffset, groundZ, at);
    time += horizontal(corner, at) / options.stationSpeed + options.legBuffer;
    s.firstMeeting = {corner, time};
    at = corner;
  }
  return plan;
}

size_t meetingToServe(const std::vector<double>& times, double now) {
  if (times.empty() || times.front() <= now) return 0;
  size_t overdue = times.size();
  for (size_t i = 1; i < times.size(); ++i)
    if (times[i] < now && (overdue == times.size() || times[i] < times[overdue])) overdue = i;
  return overdue == times.size() ? 0 : overdue;
}

planning::GroundGrid stationGroundGrid(const std::vector<agent::BoxView>& boxes,
                                       const planning::Vec2& also, double radius,
                                       bool blockFootprints) {
  planning::Vec2 low = also, high = also;
  for (const auto& box : boxes)
    for (const double sx : {-0.5, 0.5})
      for (const double sy : {-0.5, 0.5}) {
        const Vec3 corner =
            box.center + box.rotation * Vec3(sx * box.size.x(), sy * box.size.y(), 0);
        low = low.cwiseMin(corner.head<2>());
        high = high.cwiseMax(corner.head<2>());
      }
  const planning::Vec2 margin = planning::Vec2::Constant(kGroundMargin);
  planning::GroundGrid ground(low - margin, high + margin, kGroundCell);
  if (!blockFootprints) return ground;
  for (const auto& box : boxes) {
    // Boxes turn about the vertical only; a box standing on its side keeps its x axis.
    const planning::Vec2 axis = box.rotation.col(0).head<2>();
    ground.blockRectangle(box.center.head<2>(), axis.norm() > 1e-6 ? axis : planning::Vec2::UnitX(),
                          0.5 * box.size.head<2>(), radius + kGroundClearance);
  }
  return ground;
}

size_t blockGroundObstacles(planning::GroundGrid& ground,
                            const std::vector<Eigen::Vector3f>& points, double groundZ,
                            double inflate) {
  constexpr double kLow = 0.3, kHigh = 2.0;  // m above the ground: a ground vehicle's height
  const double cell = ground.resolution();
  std::unordered_set<int64_t> done;
  size_t newly = 0;
  for (const auto& point : points) {
    const double height = point.z() - groundZ;
    if (height < kLow || height > kHigh) continue;
    const auto x = static_cast<int64_t>(std::floor(point.x() / cell));
    const auto y = static_cast<int64_t>(std::floor(point.y() / cell));
    if (!done.insert(x * 1000003 + y).second) continue;
    newly += ground.blockDisc(planning::Vec2((x + 0.5) * cell, (y + 0.5) * cell), inflate);
  }
  return newly;
}

}  // namespace coinspect::strategies::slei
