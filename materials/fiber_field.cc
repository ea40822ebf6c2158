// Fiber direction fields: constant and rotating through the thickness.
#include "materials/fiber_field.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vulnus::materials
{
Vector3 fiber_direction(const FiberFieldParameters& parameters, const Vector3& x)
{
  const double direction_norm = parameters.direction.norm();
  if (!(direction_norm > 0.0))
    throw std::invalid_argument("Fiber direction: must be a nonzero vector; give e.g. 1,0,0");
  const Vector3 a = parameters.direction / direction_norm;
  if (parameters.kind == FiberFieldParameters::Kind::constant)
    return a;

  const double axis_norm = parameters.axis.norm();
  if (!(axis_norm > 0.0))
    throw std::invalid_argument("Fiber rotation axis: must be a nonzero vector; give e.g. 0,1,0");
  const double length = parameters.end_coordinate - parameters.start_coordinate;
  if (!(std::abs(length) > 0.0))
    throw std::invalid_argument("Fiber rotation end: must differ from the start coordinate; "
                                "give the positions of the entrance and exit faces");
  const Vector3 axis = parameters.axis / axis_norm;
  const double s = std::clamp((x.dot(axis) - parameters.start_coordinate) / length, 0.0, 1.0);
  constexpr double pi = 3.14159265358979323846;
  const double angle = s * parameters.total_angle_degrees * pi / 180.0;
  return Eigen::AngleAxisd(angle, axis) * a;
}
} // namespace vulnus::materials
