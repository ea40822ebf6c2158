// The path's span inside boxes and spheres, and the reach of a body's shape along a direction.
#include "mpm/target_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vulnus::mpm
{
PathThroughBox path_through_box(const Vector3& lower, const Vector3& upper, const Vector3& origin,
                                const Vector3& direction)
{
  // Slab method: the path is inside the box between the last entry into and the first exit
  // from the three pairs of parallel planes.
  PathThroughBox path;
  double t_in = -std::numeric_limits<double>::infinity();
  double t_out = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d)
  {
    if (std::abs(direction[d]) < 1e-12)
    {
      if (origin[d] < lower[d] || origin[d] > upper[d])
        return path;
      continue;
    }
    const bool forward = direction[d] > 0.0;
    const double t_lower = (lower[d] - origin[d]) / direction[d];
    const double t_upper = (upper[d] - origin[d]) / direction[d];
    const double enter = forward ? t_lower : t_upper, leave = forward ? t_upper : t_lower;
    if (enter > t_in)
    {
      t_in = enter;
      path.entrance_face = 2 * d + (forward ? 0 : 1);
    }
    if (leave < t_out)
    {
      t_out = leave;
      path.exit_face = 2 * d + (forward ? 1 : 0);
    }
  }
  if (!(t_in < t_out) || path.entrance_face < 0 || path.exit_face < 0)
    return PathThroughBox();
  path.hits = true;
  path.t_in = t_in;
  path.t_out = t_out;
  return path;
}

PathSpan path_through_body(const BodyParameters& body, const Vector3& origin,
                           const Vector3& direction)
{
  PathSpan span;
  if (body.shape == BodyShape::box)
  {
    const PathThroughBox box = path_through_box(body.box_min, body.box_max, origin, direction);
    span.hits = box.hits;
    span.t_in = box.t_in;
    span.t_out = box.t_out;
  }
  else if (body.shape == BodyShape::sphere)
  {
    const Vector3 offset = origin - body.center;
    const double middle = -offset.dot(direction);
    const double miss_squared = (offset + middle * direction).squaredNorm();
    const double half_chord_squared = body.radius * body.radius - miss_squared;
    if (half_chord_squared > 0.0)
    {
      span.hits = true;
      span.t_in = middle - std::sqrt(half_chord_squared);
      span.t_out = middle + std::sqrt(half_chord_squared);
    }
  }
  else
    span.shape_known = false;
  return span;
}

double reach_along(const BodyParameters& body, const Vector3& direction)
{
  switch (body.shape)
  {
  case BodyShape::box:
  {
    double reach = 0.0;
    for (int d = 0; d < 3; ++d)
      reach += std::max(body.box_min[d] * direction[d], body.box_max[d] * direction[d]);
    return reach;
  }
  case BodyShape::sphere:
    return body.center.dot(direction) + body.radius;
  case BodyShape::cylinder:
  {
    // A disc of radius R normal to the axis a reaches R sqrt(1 - (a . d)^2) beyond its
    // centre; a hemispherical nose is a sphere of radius R about the nose's base.
    const double along_axis = body.axis.dot(direction);
    const double rim = body.radius * std::sqrt(std::max(0.0, 1.0 - along_axis * along_axis));
    const double tail = body.center.dot(direction) + rim;
    if (body.nose == NoseShape::flat)
      return std::max(tail, (body.center + body.length * body.axis).dot(direction) + rim);
    const Vector3 nose_base = body.center + (body.length - body.radius) * body.axis;
    const double nose = nose_base.dot(direction) + (along_axis >= 0.0 ? body.radius : rim);
    return std::max(tail, nose);
  }
  }
  return 0.0;
}
} // namespace vulnus::mpm
