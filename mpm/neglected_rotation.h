// The rotation a rigid body that only translates leaves out (a free rigid projectile: the
// solver moves rigid bodies without turning them). The contact's angular impulse about the
// mass centre c, L(t) = int (M_O - c x F) dt with M_O the contact's moment about x = 0 and F
// its force, would turn the body at omega = I^-1 L (I about c at the start; small angles), by
// the angle theta = int |omega| dt, and move its farthest point (r from c) by r theta. Past a
// quarter of a cell the translation-only answer is no longer the body's, and the run says so.
// The same estimate releases a projectile held rigid while elastic (mpm/rigid_hold.h) at a
// tenth of a cell.
#pragma once

#include "mpm/particles.h"

#include <Eigen/Core>

#include <vector>

namespace vulnus::mpm
{
class NeglectedRotation
{
public:
  /// Limit of the farthest point's travel, in cells.
  static constexpr double drift_cells = 0.25;

  /// Starts the estimate for a body of mass centre `centre`, inertia `inertia` about it and
  /// farthest point `radius` (m) from it, on cells of edge `cell_size` (m).
  void begin(const Vector3& centre, const Eigen::Matrix3d& inertia, double radius,
             double cell_size);
  bool active() const { return started; }
  /// After a step's contact: the contact's total force on the body and its moment about x = 0,
  /// the velocity the body moved with over the step dt, and the step's end (number, time).
  void add(const Vector3& force, const Vector3& moment_about_origin, const Vector3& velocity,
           double dt, long step, double time);
  double angle() const { return rotation_angle; }                ///< rad
  double drift() const { return rotation_angle * radius; }       ///< m
  double drift_limit() const { return drift_cells * cell_size; } ///< m
  /// The step at whose end the drift first passed the limit (-1: not yet), and its time (s).
  long exceeded_step() const { return first_step_beyond; }
  double exceeded_time() const { return first_time_beyond; }

  /// The evolving state as numbers and back (checkpoints).
  std::vector<double> packed() const;
  void unpack(const std::vector<double>& values);

private:
  bool started = false;
  double cell_size = 0.0;
  double radius = 0.0;
  Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Zero();
  Vector3 centre = Vector3::Zero();
  Vector3 angular_momentum = Vector3::Zero();
  double rotation_angle = 0.0;
  long first_step_beyond = -1;
  double first_time_beyond = 0.0;
};
} // namespace vulnus::mpm
