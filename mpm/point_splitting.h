// Point splitting: a point whose domain has been stretched along one of its edges beyond a
// length (in cells) becomes two points, each half of it along that edge. Where tissue flows
// around a projectile its points are drawn apart, in 3D along the hoop direction too, and two
// points per cell axis then sample the stretched material too coarsely (docs/point_splitting.md);
// splitting puts points back where the material stretched, and nowhere else.
#pragma once

#include "mpm/particles.h"
#include "mpm/symmetry_planes.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace vulnus::mpm
{
struct PointSplitting
{
  /// A point splits once one of its domain's edges is longer than this, m (0: never).
  double longest_edge = 0.0;
  /// The children must stay inside this box (the grid's nodes) and on the modelled side of
  /// each plane.
  Vector3 lower = Vector3::Constant(-1e300), upper = Vector3::Constant(1e300);
  std::vector<SymmetryPlane> planes;
  /// Whether a child at x would sit inside a rigid body (it is then not made); may be empty.
  std::function<bool(const Vector3&)> inside_rigid;
};

/// Splits the points [begin, end) of one body whose longest domain edge exceeds the limit
/// (debris excepted: it carries pressure alone, and flies apart freely where it is not
/// compressed, so its domain measures no material the grid should sample better):
/// each keeps one half (moved by a quarter of that edge) and the other half is returned, one
/// point per split, as a one-body container with the parent's state and id (fresh ids are the
/// caller's). Mass, volume and stored energy are halved between the two; velocity, F, stress
/// and history are the parent's, so the body's mass, momentum, mass centre and energy are
/// unchanged. A point whose child would leave the box or cross a plane is not split.
Particles split_stretched_points(Particles& particles, std::size_t begin, std::size_t end,
                                 const PointSplitting& settings);
} // namespace vulnus::mpm
