// Signed distances to spheres, boxes and cylinders (flat or hemispherical nose).
#include "mpm/shape_distance.h"

#include <algorithm>
#include <cmath>

namespace vulnus::mpm
{
namespace
{
/// Distance to the box |p_i| <= half_i (centred at the origin), n = 2 or 3 axes.
template <int n> ShapeDistance box_distance(const double* p, const double* half, Vector3 axes[n])
{
  double q[n], outside2 = 0.0, largest = -std::numeric_limits<double>::max();
  int largest_axis = 0;
  for (int i = 0; i < n; ++i)
  {
    q[i] = std::abs(p[i]) - half[i];
    outside2 += q[i] > 0.0 ? q[i] * q[i] : 0.0;
    if (q[i] > largest)
    {
      largest = q[i];
      largest_axis = i;
    }
  }
  ShapeDistance result;
  if (outside2 > 0.0)
  {
    const double outside = std::sqrt(outside2);
    result.distance = outside;
    for (int i = 0; i < n; ++i)
      if (q[i] > 0.0)
        result.normal += (std::copysign(q[i], p[i]) / outside) * axes[i];
    return result;
  }
  result.distance = largest;
  result.normal = std::copysign(1.0, p[largest_axis]) * axes[largest_axis];
  return result;
}

ShapeDistance sphere_distance(const Vector3& center, const double radius, const Vector3& x)
{
  const Vector3 d = x - center;
  const double r = d.norm();
  ShapeDistance result;
  result.distance = r - radius;
  if (r > 0.0)
    result.normal = d / r;
  return result;
}

/// A flat cylinder from `tail` along unit `axis` over [0, length], of `radius`.
ShapeDistance flat_cylinder_distance(const Vector3& tail, const Vector3& axis, const double length,
                                     const double radius, const Vector3& x)
{
  const Vector3 d = x - tail;
  const double along = d.dot(axis);
  const Vector3 radial_vector = d - along * axis;
  const double r = radial_vector.norm();
  Vector3 axes[2];
  if (r > 0.0)
    axes[0] = radial_vector / r;
  else // on the axis: any direction across it
    axes[0] = axis.unitOrthogonal();
  axes[1] = axis;
  const double p[2] = {r, along - 0.5 * length};
  const double half[2] = {radius, 0.5 * length};
  return box_distance<2>(p, half, axes);
}
} // namespace

ShapeDistance distance_to_shape(const BodyParameters& body, const Vector3& offset,
                                const Vector3& x)
{
  switch (body.shape)
  {
    case BodyShape::sphere:
      return sphere_distance(body.center + offset, body.radius, x);
    case BodyShape::box:
    {
      const Vector3 centre = 0.5 * (body.box_min + body.box_max) + offset;
      const Vector3 half_size = 0.5 * (body.box_max - body.box_min);
      const Vector3 p = x - centre;
      Vector3 axes[3] = {Vector3::UnitX(), Vector3::UnitY(), Vector3::UnitZ()};
      return box_distance<3>(p.data(), half_size.data(), axes);
    }
    case BodyShape::cylinder:
    {
      const Vector3 axis = body.axis.normalized();
      const Vector3 tail = body.center + offset;
      if (body.nose == NoseShape::flat)
        return flat_cylinder_distance(tail, axis, body.length, body.radius, x);
      const double shank = body.length - body.radius;
      const ShapeDistance nose = sphere_distance(tail + shank * axis, body.radius, x);
      if (!(shank > 0.0))
        return nose;
      const ShapeDistance rest = flat_cylinder_distance(tail, axis, shank, body.radius, x);
      return nose.distance < rest.distance ? nose : rest;
    }
  }
  return {};
}
} // namespace vulnus::mpm
