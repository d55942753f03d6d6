#include "coinspect/strategies/caric_baseline_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

#include "coinspect/core/error.h"

namespace coinspect::strategies::baseline {

using runtime::footprintOf;

std::vector<Team> formTeams(const std::vector<UnitStart>& units) {
  std::vector<int> explorers, photographers;
  for (int i = 0; i < static_cast<int>(units.size()); ++i) {
    if (units[i].role == agent::Role::Explorer) explorers.push_back(i);
    if (units[i].role == agent::Role::Photographer) photographers.push_back(i);
  }
  std::vector<Team> teams;
  if (explorers.empty()) {
    for (const int p : photographers)
      teams.push_back(Team{-1, {p}});
    return teams;
  }
  for (const int e : explorers)
    teams.push_back(Team{e, {}});
  const size_t capacity = (photographers.size() + explorers.size() - 1) / explorers.size();
  // Nearest pairs first; ties by photographer, then explorer (fleet order).
  std::vector<std::tuple<double, int, int>> pairs;
  for (const int p : photographers)
    for (size_t t = 0; t < teams.size(); ++t)
      pairs.emplace_back((units[p].position - units[teams[t].explorer].position).norm(), p,
                         static_cast<int>(t));
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> placed(units.size(), false);
  for (const auto& [distance, p, t] : pairs) {
    if (placed[p] || teams[t].photographers.size() >= capacity) continue;
    teams[t].photographers.push_back(p);
    placed[p] = true;
  }
  for (auto& team : teams)
    std::sort(team.photographers.begin(), team.photographers.end());
  return teams;
}

Vec3 teamStart(const Team& team, const std::vector<UnitStart>& units) {
  if (team.explorer >= 0) return units[team.explorer].position;
  Vec3 sum = Vec3::Zero();
  for (const int p : team.photographers)
    sum += units[p].position;
  return team.photographers.empty() ? sum : Vec3(sum / team.photographers.size());
}

double boxWorkload(const BoxView& box) {
  const auto footprint = footprintOf(box);
  const double a = 2.0 * footprint.half[0], b = 2.0 * footprint.half[1];
  const double h = box.size[runtime::verticalAxis(box)];
  return 2.0 * (a + b) * h + a * b;
}

std::vector<BoxView> bestFirstOrder(const std::vector<BoxView>& boxes, const Vec3& start) {
  std::vector<BoxView> out;
  std::vector<bool> used(boxes.size(), false);
  Vec3 at = start;
  for (size_t n = 0; n < boxes.size(); ++n) {
    size_t best = boxes.size();
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < boxes.size(); ++i) {
      const double d = (boxes[i].center - at).norm();
      if (!used[i] && d < bestDistance) {
        bestDistance = d;
        best = i;
      }
    }
    used[best] = true;
    out.push_back(boxes[best]);
    at = boxes[best].center;
  }
  return out;
}

namespace {

// Cuts `sequence` into runs with the given shares of the total workload.
std::vector<std::vector<BoxView>> cutIntoRuns(const std::vector<BoxView>& sequence,
                                              const std::vector<double>& shares) {
  double total = 0.0;
  for (const auto& box : sequence)
    total += boxWorkload(box);
  std::vector<std::vector<BoxView>> runs(shares.size());
  size_t run = 0;
  double room = total * shares[0];
  for (BoxView box : sequence) {
    while (true) {
      const double work = boxWorkload(box);
      if (run + 1 == runs.size() || work <= room * 1.05) {
        runs[run].push_back(box);
        room -= work;
        break;
      }
      const double fraction = room / work;
      if (fraction > 0.1) {
        auto [first, rest] = runtime::cutBox(box, fraction);
        runs[run].push_back(first);
        box = rest;
      }
      ++run;
      room = total * shares[run];
    }
  }
  return runs;
}

}  // namespace

std::vector<std::vector<BoxView>> assignBoxes(const std::vector<BoxView>& boxes,
                                              const std::vector<Team>& teams,
                                              const std::vector<UnitStart>& units) {
  if (teams.empty()) return {};
  if (boxes.empty()) return std::vector<std::vector<BoxView>>(teams.size());
  Vec3 mean = Vec3::Zero();
  for (const auto& team : teams)
    mean += teamStart(team, units);
  mean /= static_cast<double>(teams.size());
  const auto sequence = bestFirstOrder(boxes, mean);
  double members = 0.0;
  for (const auto& team : teams)
    members += static_cast<double>(std::max<size_t>(team.size(), 1));

  // order[k]: the team that takes the k-th run.
  std::vector<int> order(teams.size());
  std::iota(order.begin(), order.end(), 0);
  const auto evaluate = [&](const std::vector<int>& candidate,
                            std::vector<std::vector<BoxView>>* runsOut) {
    std::vector<double> shares;
    for (const int t : candidate)
      shares.push_back(static_cast<double>(std::max<size_t>(teams[t].size(), 1)) / members);
    auto runs = cutIntoRuns(sequence, shares);
    double cost = 0.0;
    for (size_t k = 0; k < runs.size(); ++k)
      if (!runs[k].empty())
        cost += (runs[k].front().center - teamStart(teams[candidate[k]], units)).norm();
    if (runsOut) *runsOut = std::move(runs);
    return cost;
  };
  std::vector<int> best = order;
  if (teams.size() <= 6) {
    double bestCost = std::numeric_limits<double>::infinity();
    do {
      const double cost = evaluate(order, nullptr);
      if (cost < bestCost - 1e-9) {
        bestCost = cost;
        best = order;
      }
    } while (std::next_permutation(order.begin(), order.end()));
  }
  std::vector<std::vector<BoxView>> runs;
  evaluate(best, &runs);
  std::vector<std::vector<BoxView>> out(teams.size());
  for (size_t k = 0; k < runs.size(); ++k)
    out[best[k]] = std::move(runs[k]);
  return out;
}

std::vector<Layer> layersOf(const std::vector<BoxView>& boxes, double layerHeight, double minZ,
                            double distance) {
  std::vector<Layer> out;
  bool upwards = true;
  for (const auto& box : boxes) {
    auto heights = runtime::boxLayers(box, layerHeight, minZ);
    if (!upwards) std::reverse(heights.begin(), heights.end());
    const double length = footprintOf(box).perimeterAt(distance);
    for (const double z : heights)
      out.push_back(Layer{box, z, length});
    upwards = !upwards;
  }
  return out;
}

std::vector<std::vector<Layer>> divideLayers(const std::vector<Layer>& layers, size_t parts) {
  std::vector<std::vector<Layer>> out(parts);
  if (parts == 0) return out;
  double total = 0.0;
  for (const auto& layer : layers)
    total += layer.length;
  double before = 0.0;
  for (const auto& layer : layers) {
    // The part whose share holds the middle of this layer's length.
    const double middle = total > 0.0 ? (before + 0.5 * layer.length) / total : 0.0;
    const size_t part = std::min(parts - 1, static_cast<size_t>(middle * parts));
    out[part].push_back(layer);
    before += layer.length;
  }
  return out;
}

void requeueFailedLayer(std::vector<Layer>& layers, size_t index) {
  COINSPECT_ASSERT(index < layers.size());
  if (layers[index].retry) return;
  Layer again = layers[index];
  again.retry = true;
  layers.push_back(again);
}

}  // namespace coinspect::strategies::baseline
