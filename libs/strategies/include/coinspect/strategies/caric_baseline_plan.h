// The pure planning of `caric-baseline` (the CARIC organisers' baseline / team XXH): teams, box
// assignment and layers. Every unit computes the same plan from the same start positions, so
// the fleet agrees without messages.
#pragma once

#include <string>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/strategies/runtime/box_geometry.h"

namespace coinspect::strategies::baseline {

using agent::BoxView;
using agent::Vec3;

struct UnitStart {
  std::string name;
  agent::Role role = agent::Role::Photographer;
  Vec3 position = Vec3::Zero();
};

// Indices into the units given to formTeams.
struct Team {
  int explorer = -1;               // -1: a team of photographers only
  std::vector<int> photographers;  // fleet order
  size_t size() const { return photographers.size() + (explorer >= 0 ? 1 : 0); }
};

// One team per explorer (fleet order); each photographer joins the nearest explorer that still
// has room (at most ceil(photographers / explorers) each), nearest pairs first, ties to the
// lower index. Without explorers every photographer is a team. Ground stations join nothing.
std::vector<Team> formTeams(const std::vector<UnitStart>& units);

// Where a team starts: its explorer, else the mean of its photographers.
Vec3 teamStart(const Team& team, const std::vector<UnitStart>& units);

// Inspection work of a box: its side and top areas (m^2).
double boxWorkload(const BoxView& box);

// Greedy nearest-neighbour order of the boxes' centres from `start` (ties: lower index).
std::vector<BoxView> bestFirstOrder(const std::vector<BoxView>& boxes, const Vec3& start);

// Cuts the best-first sequence of boxes (from the teams' mean start) into one run per team,
// proportional to team size (a box on a cut is split along its longest side); the teams take the
// runs in the order that minimises the sum of distances from each team's start to its first box
// (tried exhaustively up to 6 teams). Result: per team, its boxes in visiting order.
std::vector<std::vector<BoxView>> assignBoxes(const std::vector<BoxView>& boxes,
                                              const std::vector<Team>& teams,
                                              const std::vector<UnitStart>& units);

// One standoff orbit to fly: around `box` at height `z`.
struct Layer {
  BoxView box;
  double z = 0.0;
  double length = 0.0;  // m, orbit length at the planned distance
  bool retry = false;   // a second try, queued after its first flight failed
};

// The flight to `layers[index]` failed: unless that was already its second try, the layer is
// queued again at the end. A unit on the ground near a tower cannot plan out of its take-off
// column until the LiDAR has mapped the space around it (unknown space near a box is blocked),
// so the first layers' flights fail within seconds; dropping them for good lost an explorer's
// whole share (CARIC MBS seed 1: raffles hovered from 210 s to the end).
void requeueFailedLayer(std::vector<Layer>& layers, size_t index);

// The layers of every box in order, no taller than `layerHeight`, at least `minZ` high;
// alternately bottom-up and top-down from box to box (a snake: the next box starts near where
// the last one ended).
std::vector<Layer> layersOf(const std::vector<BoxView>& boxes, double layerHeight, double minZ,
                            double distance);

// Splits the layers into `parts` consecutive runs of about equal orbit length (some may be
// empty when there are fewer layers than parts).
std::vector<std::vector<Layer>> divideLayers(const std::vector<Layer>& layers, size_t parts);

}  // namespace coinspect::strategies::baseline
