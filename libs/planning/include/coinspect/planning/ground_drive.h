// How a ground vehicle without a map of its own (a SLEI3D ground station) drives to a place:
// along GroundGrid paths over what it knows for good (the boxes' footprints, walls seen in
// LiDAR points), plus its guesses: where it stood still while driving, it blocks the ground
// just ahead of it and plans again (the simulator stops a ground vehicle at a structure).
// Guesses can wall it in (a slei-c station that stood at a crossing for long blocked every way
// out and then drove straight into a wall for 1800 s): with no path out it forgets them and
// plans on what it knows for good; a place no known path reaches, it drives to the nearest
// cell that one reaches.
#pragma once

#include <cstddef>
#include <vector>

#include "coinspect/planning/ground_path.h"

namespace coinspect::planning {

struct GroundDriveOptions {
  double arrived = 0.5;        // m from the goal (or the end of its path) that counts as there
  double stuckDistance = 0.2;  // m: moved less than this ...
  double stuckTime = 3.0;      // s ... for this long while driving: blocked
  double blockAhead = 0.8;     // m ahead of it, the centre of the disc it then blocks
  double blockRadius = 0.7;    // m
};

class GroundDrive {
 public:
  GroundDrive(GroundGrid known, const GroundDriveOptions& options = {});

  // Ground learnt for good: `block(grid)` blocks it on a grid and returns the cells it newly
  // blocked; applied to what it knows and to what it drives on. Returns the count on the first.
  template <class Block>
  size_t learn(Block&& block) {
    const size_t known = block(known_);
    if (block(ground_) > 0 || known > 0) replan_ = true;
    return known;
  }

  // The place to drive to now, standing at `at` at `time`, on the way to `goal`.
  Vec2 step(const Vec2& at, const Vec2& goal, double time);

  // At the last step, on the way to `goal`, it stood at it or at the end of a path that stops
  // short of it (the goal lies where no known path reaches): as near as it gets.
  bool there(const Vec2& goal) const;
  const GroundGrid& ground() const { return ground_; }  // known and guessed
  size_t guesses() const { return guesses_; }           // discs blocked since the last forgetting
  size_t forgotten() const { return forgotten_; }       // times it forgot its guesses

 private:
  void plan(const Vec2& at, const Vec2& goal);
  void dropPassed(const Vec2& at);  // waypoints within `arrived` of it, but the last

  GroundDriveOptions options_;
  GroundGrid known_, ground_;
  std::vector<Vec2> path_;  // waypoints to the goal, the last one the goal or nearest to it
  Vec2 goal_ = Vec2::Constant(1e300);
  bool replan_ = true;
  bool started_ = false, there_ = false;
  Vec2 lastMoved_ = Vec2::Zero();  // where it was when it last moved
  double lastMovedTime_ = 0.0;
  size_t guesses_ = 0, forgotten_ = 0;
};

}  // namespace coinspect::planning
