// Geometry of the mission's bounding boxes, as strategies use them: the region to plan in,
// splitting a box into parts, horizontal layers, standoff orbits around a layer, box faces.
//
// Boxes may be rotated; "vertical" below means the box axis closest to world z, and footprints
// are the box's section across that axis projected on the ground plane (exact for the yaw-only
// boxes of every CARIC and generated scenario).
#pragma once

#include <Eigen/Core>

#include <utility>
#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::strategies::runtime {

using agent::BoxView;
using agent::Vec3;
using Vec2 = Eigen::Vector2d;

struct Aabb {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
  Vec3 centre() const { return 0.5 * (min + max); }
  Vec3 size() const { return max - min; }
  bool contains(const Vec3& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
};

// World-aligned bounds of one box (its 8 corners).
Aabb boxBounds(const BoxView& box);

// The planning region of a mission: the bounds of every box grown by `margin` sideways and on
// top, from `groundZ` up (robots take off from the ground, which is below every box).
Aabb missionRegion(const std::vector<BoxView>& boxes, double margin, double groundZ);

// Index (0, 1, 2) of the box's longest edge; ties go to the lower index.
int longestAxis(const BoxView& box);
// Index of the box axis closest to world z.
int verticalAxis(const BoxView& box);

// Cuts a box across its longest edge at `fraction` (0, 1) of that edge: (first part, rest).
std::pair<BoxView, BoxView> cutBox(const BoxView& box, double fraction);
// Splits a box into `parts` equal boxes along its longest edge, in order along that axis.
std::vector<BoxView> splitBox(const BoxView& box, int parts);

// The box extended downwards (along its vertical axis) to world height `groundZ`: the space a
// structure standing in the box may occupy below it.
BoxView extendToGround(const BoxView& box, double groundZ);

// World heights of the centres of the layers that slice the box's bounds into slices no taller
// than `layerHeight`, bottom to top, each raised to at least `minZ`, duplicates removed.
std::vector<double> boxLayers(const BoxView& box, double layerHeight, double minZ);

// The box's section across its vertical axis, on the ground plane: a rectangle.
struct Footprint {
  Vec2 centre = Vec2::Zero();
  Vec2 axis[2] = {Vec2::UnitX(), Vec2::UnitY()};  // unit, orthogonal, counter-clockwise
  double half[2] = {0.0, 0.0};                    // half extents along the axes
  double perimeterAt(double distance) const;      // length of the standoff orbit at `distance`
};
Footprint footprintOf(const BoxView& box);

// A closed counter-clockwise loop at height `z`, at `distance` from the footprint everywhere
// (straight sides along the footprint's edges, quarter circles around its corners), sampled
// about every `spacing` m (the first point is not repeated at the end). The first point is the
// one nearest `near` (horizontally).
std::vector<Vec3> standoffOrbit(const BoxView& box, double z, double distance, double spacing,
                                const Vec3& near);

// The point of the box (solid) nearest `p`, and the distance to it (0 inside).
Vec3 closestPointOnBox(const BoxView& box, const Vec3& p);
double distanceToBox(const BoxView& box, const Vec3& p);

// One face of a box: centre, outward unit normal, the two in-face unit axes and half extents.
struct BoxFace {
  Vec3 centre = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  Vec3 axis[2] = {Vec3::UnitX(), Vec3::UnitY()};
  double half[2] = {0.0, 0.0};
  double area() const { return 4.0 * half[0] * half[1]; }
};
// The 6 faces: -x, +x, -y, +y, -z, +z of the box's own axes.
std::vector<BoxFace> boxFaces(const BoxView& box);

}  // namespace coinspect::strategies::runtime
