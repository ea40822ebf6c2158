// Signed distance to a body's exact shape (sphere, box, flat or round-nosed cylinder) and the
// outward normal there: the surface a rigid body's contact measures its gap from
// (Contact/Rigid surface = exact), instead of the mass centres its points give a node.
#pragma once

#include "mpm/scene_parameters.h"

namespace vulnus::mpm
{
struct ShapeDistance
{
  /// Distance from the point to the surface, m: negative inside the body. Exact for spheres,
  /// boxes and flat cylinders; for a round nose the smaller of the shank's and the nose's,
  /// exact outside the body and a bound inside.
  double distance = 0.0;
  /// Outward unit normal of the nearest surface (the distance's gradient), or zero where it
  /// is not defined (the centre of a sphere).
  Vector3 normal = Vector3::Zero();
};

/// The distance from `x` to the shape of `body` moved rigidly by `offset`.
ShapeDistance distance_to_shape(const BodyParameters& body, const Vector3& offset,
                                const Vector3& x);
} // namespace vulnus::mpm
