// Fiber direction fields of the tissue: a constant direction, or a direction rotating about
// the through-thickness axis from the entrance face to the exit face (paper Fig. 1a).
#pragma once

#include "materials/material.h"

namespace vulnus::materials
{
/// Reference fiber direction a0(x).
///
/// constant: a0 = direction everywhere.
/// rotating: with s = clamp((x . axis - start_coordinate) / (end_coordinate -
///   start_coordinate), 0, 1), a0 = R(axis, s * total_angle) direction with R the
///   right-handed rotation about +axis: the direction turns CLOCKWISE by s * total_angle when
///   viewed looking along +axis (from the entrance side towards the exit side, as the bullet
///   sees it when it travels along +axis). Example: axis z, direction x, 90 deg gives y.
///   Points before the start face get `direction`, points beyond the end face the fully
///   rotated direction. A direction perpendicular to the axis
///   stays perpendicular. Paper: axis y, direction in the x-z plane, total angle 180 deg.
struct FiberFieldParameters
{
  enum class Kind
  {
    constant,
    rotating
  };
  Kind kind = Kind::constant;
  Vector3 direction = Vector3::UnitX(); ///< at the start face; normalized on use
  Vector3 axis = Vector3::UnitY();      ///< through-thickness axis; normalized on use
  double start_coordinate = 0.0;        ///< m, position of the entrance face along axis
  double end_coordinate = 0.01;         ///< m, position of the exit face along axis
  double total_angle_degrees = 180.0;   ///< clockwise seen along +axis
};

/// Unit fiber direction at the point x (m). Throws std::invalid_argument for a zero
/// direction or axis, or equal start and end coordinates of a rotating field.
Vector3 fiber_direction(const FiberFieldParameters& parameters, const Vector3& x);
} // namespace vulnus::materials
