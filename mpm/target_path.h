// Where the projectile's path meets the target as the deck draws it: the span of a straight
// path inside a body's shape (a box's faces, a sphere), and how far a body reaches along a
// direction. Depth, cavity and exit are measured from these surfaces, not from the points
// that discretise them (half a point spacing inside the faces).
#pragma once

#include "mpm/scene_parameters.h"

namespace vulnus::mpm
{
/// Where a straight path (origin + t direction, direction unit) crosses a box.
struct PathThroughBox
{
  bool hits = false;
  int entrance_face = -1, exit_face = -1; ///< 0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+
  double t_in = 0.0, t_out = 0.0;         ///< m along the path
  double length() const { return hits ? t_out - t_in : 0.0; }
};

PathThroughBox path_through_box(const Vector3& lower, const Vector3& upper, const Vector3& origin,
                                const Vector3& direction);

/// The part of a straight path inside a body's shape, [t_in, t_out] in m along the path.
struct PathSpan
{
  bool shape_known = true; ///< false: a shape without a closed form here (cylinder targets)
  bool hits = false;
  double t_in = 0.0, t_out = 0.0;
};

PathSpan path_through_body(const BodyParameters& body, const Vector3& origin,
                           const Vector3& direction);

/// The largest x . direction over the body's shape (its front along `direction`), m.
double reach_along(const BodyParameters& body, const Vector3& direction);
} // namespace vulnus::mpm
