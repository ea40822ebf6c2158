// The checks that keep an elastic projectile rigid, and their record.
#include "mpm/rigid_hold.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace vulnus::mpm
{
bool RigidHold::begin(const RigidHoldLimits& l, const double impact_pressure, const Vector3& c,
                      const Eigen::Matrix3d& inertia, const double r)
{
  limits = l;
  state = RigidHoldRecord{};
  state.impact_pressure = impact_pressure;
  centre = c;
  radius = r;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(inertia);
  // Points on a line have no inertia about it, and nothing to turn: no rotation is neglected.
  inverse_inertia = lu.isInvertible() ? Eigen::Matrix3d(lu.inverse()) : Eigen::Matrix3d::Zero();
  if (!(limits.yield_stress > 0.0))
  {
    state.reason = "its law has no yield stress to hold it against";
    return false;
  }
  state.applies = true;
  if (impact_pressure >= pressure_limit())
  {
    std::ostringstream o;
    o << std::setprecision(3) << "the acoustic impact pressure " << impact_pressure / 1e6 << " MPa is "
      << impact_pressure / limits.yield_stress << " of its yield stress, above the limit "
      << limits.stress_fraction;
    state.reason = o.str();
    return false;
  }
  state.held = true;
  return true;
}

bool RigidHold::check(const double peak_node_force, const Vector3& force,
                      const Vector3& moment_about_origin, const Vector3& velocity, const double dt,
                      const long step, const double time)
{
  if (!state.held)
    return true;
  // Averaged over the time the projectile takes to cross a cell, at most window_steps of
  // this step: a slow or resting projectile's steady load is read as it is.
  const double speed = velocity.norm();
  const double crossing = speed * window_steps * dt > limits.cell_size
                            ? limits.cell_size / speed
                            : window_steps * dt;
  window.emplace_back(dt, peak_node_force);
  double span = 0.0, impulse = 0.0;
  for (const auto& [step_dt, force] : window)
  {
    span += step_dt;
    impulse += step_dt * force;
  }
  while (window.size() > 1 && span - window.front().first >= crossing)
  {
    span -= window.front().first;
    impulse -= window.front().first * window.front().second;
    window.pop_front();
  }
  // Before the first cell's crossing has passed, the missing time had no force.
  const double pressure =
    impulse / std::max(span, crossing) / (limits.cell_size * limits.cell_size);
  if (pressure > state.peak_pressure)
  {
    state.peak_pressure = pressure;
    state.peak_pressure_time = time;
  }

  // About the mass centre where the step's contact found the body, then moved with it.
  angular_momentum += dt * (moment_about_origin - centre.cross(force));
  centre += dt * velocity;
  rotation_angle += dt * (inverse_inertia * angular_momentum).norm();
  state.rotation_drift = rotation_angle * radius;

  std::ostringstream why;
  why << std::setprecision(3);
  if (pressure > pressure_limit())
    why << "the contact pressure on it reached " << pressure / 1e6 << " MPa, "
        << pressure / limits.yield_stress << " of its yield stress (limit "
        << limits.stress_fraction << ")";
  else if (state.rotation_drift > drift_limit())
    why << "the contact's moment would have turned it by " << rotation_angle
        << " rad, moving its farthest point " << state.rotation_drift / limits.cell_size
        << " cells (limit " << limits.drift_cells << ")";
  else
    return true;
  release(why.str(), step, time);
  return false;
}

void RigidHold::decline(const std::string& why)
{
  state = RigidHoldRecord{};
  state.applies = true;
  state.reason = why;
}

void RigidHold::release(const std::string& why, const long step, const double time)
{
  if (!state.held)
    return;
  state.held = false;
  state.release_step = step;
  state.release_time = time;
  state.reason = why;
}

std::vector<double> RigidHold::packed() const
{
  std::vector<double> v = {double(state.applies),
                           double(state.held),
                           state.impact_pressure,
                           state.peak_pressure,
                           state.peak_pressure_time,
                           state.rotation_drift,
                           double(state.release_step),
                           state.release_time,
                           centre[0],
                           centre[1],
                           centre[2],
                           angular_momentum[0],
                           angular_momentum[1],
                           angular_momentum[2],
                           rotation_angle,
                           double(window.size())};
  for (const auto& [dt, force] : window)
    v.insert(v.end(), {dt, force});
  return v;
}

void RigidHold::unpack(const std::vector<double>& v, const std::string& reason)
{
  if (v.size() < 16 || v.size() != 16 + 2 * static_cast<std::size_t>(v[15]))
    throw std::runtime_error("checkpoint is inconsistent (rigid projectile hold)");
  state.applies = v[0] != 0.0;
  state.held = v[1] != 0.0;
  state.impact_pressure = v[2];
  state.peak_pressure = v[3];
  state.peak_pressure_time = v[4];
  state.rotation_drift = v[5];
  state.release_step = static_cast<long>(v[6]);
  state.release_time = v[7];
  state.reason = reason;
  centre = Vector3(v[8], v[9], v[10]);
  angular_momentum = Vector3(v[11], v[12], v[13]);
  rotation_angle = v[14];
  window.clear();
  for (std::size_t k = 16; k + 1 < v.size(); k += 2)
    window.emplace_back(v[k], v[k + 1]);
}
} // namespace vulnus::mpm
