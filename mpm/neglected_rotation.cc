// The rotation neglected by a rigid body that only translates.
#include "mpm/neglected_rotation.h"

#include <Eigen/LU>

#include <stdexcept>

namespace vulnus::mpm
{
void NeglectedRotation::begin(const Vector3& c, const Eigen::Matrix3d& inertia, const double r,
                              const double h)
{
  *this = NeglectedRotation{};
  started = true;
  cell_size = h;
  radius = r;
  centre = c;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(inertia);
  // Points on a line have no inertia about it, and nothing to turn: no rotation is neglected.
  inverse_inertia = lu.isInvertible() ? Eigen::Matrix3d(lu.inverse()) : Eigen::Matrix3d::Zero();
}

void NeglectedRotation::add(const Vector3& force, const Vector3& moment_about_origin,
                            const Vector3& velocity, const double dt, const long step,
                            const double time)
{
  if (!started)
    return;
  // About the mass centre where the step's contact found the body, then moved with it.
  angular_momentum += dt * (moment_about_origin - centre.cross(force));
  centre += dt * velocity;
  rotation_angle += dt * (inverse_inertia * angular_momentum).norm();
  if (first_step_beyond < 0 && drift() > drift_limit())
  {
    first_step_beyond = step;
    first_time_beyond = time;
  }
}

std::vector<double> NeglectedRotation::packed() const
{
  return {double(started),           centre[0],           centre[1],           centre[2],
          angular_momentum[0],       angular_momentum[1], angular_momentum[2], rotation_angle,
          double(first_step_beyond), first_time_beyond};
}

void NeglectedRotation::unpack(const std::vector<double>& v)
{
  if (v.size() != 10 || (v[0] != 0.0) != started)
    throw std::runtime_error("checkpoint is inconsistent (rigid projectile's rotation)");
  centre = Vector3(v[1], v[2], v[3]);
  angular_momentum = Vector3(v[4], v[5], v[6]);
  rotation_angle = v[7];
  first_step_beyond = static_cast<long>(v[8]);
  first_time_beyond = v[9];
}
} // namespace vulnus::mpm
