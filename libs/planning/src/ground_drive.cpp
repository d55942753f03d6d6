#include "coinspect/planning/ground_drive.h"

#include <utility>

namespace coinspect::planning {

GroundDrive::GroundDrive(GroundGrid known, const GroundDriveOptions& options)
    : options_(options), known_(known), ground_(std::move(known)) {}

void GroundDrive::plan(const Vec2& at, const Vec2& goal) {
  replan_ = false;
  goal_ = goal;
  path_ = ground_.path(at, goal);
  if (path_.empty() && guesses_ > 0) {
    // Walled in by its own guesses (or the goal cut off by them): they go, what it saw stays.
    ground_ = known_;
    guesses_ = 0;
    ++forgotten_;
    path_ = ground_.path(at, goal);
  }
  if (path_.empty()) {
    // The goal lies where no known path leads: as near to it as one does. Nothing reached at
    // all (it stands walled in by what it saw): straight, and it learns by standing still.
    const Vec2 near = ground_.nearestReachable(at, goal);
    path_ = ground_.path(at, near);
    if (path_.empty()) path_ = {near};
  }
}

void GroundDrive::dropPassed(const Vec2& at) {
  while (path_.size() > 1 && (path_.front() - at).norm() <= options_.arrived)
    path_.erase(path_.begin());
}

bool GroundDrive::there(const Vec2& goal) const {
  return there_ && (goal - goal_).norm() <= 1e-6;
}

Vec2 GroundDrive::step(const Vec2& at, const Vec2& goal, double time) {
  if (!started_) {
    started_ = true;
    lastMoved_ = at;
    lastMovedTime_ = time;
  }
  if ((goal - goal_).norm() > 1e-6) replan_ = true;
  if (replan_) plan(at, goal);
  dropPassed(at);
  // At the goal, or at the end of the path when that is as near as it gets: standing, not stuck.
  there_ = (goal - at).norm() <= options_.arrived ||
           (path_.size() == 1 && (path_.front() - at).norm() <= options_.arrived);
  if ((at - lastMoved_).norm() > options_.stuckDistance || there_) {
    lastMoved_ = at;
    lastMovedTime_ = time;
  } else if (time - lastMovedTime_ > options_.stuckTime) {
    const Vec2 ahead = (path_.front() - at).normalized();
    ground_.blockDisc(at + options_.blockAhead * ahead, options_.blockRadius);
    ++guesses_;
    lastMovedTime_ = time;
    plan(at, goal);
    dropPassed(at);
  }
  return path_.front();
}

}  // namespace coinspect::planning
