// Log lines of the rigid hold of an elastic projectile.
#include "simulator/rigid_hold_report.h"

#include <iomanip>
#include <sstream>

namespace vulnus::simulator
{
std::string rigid_hold_scene_line(const mpm::Solver& solver)
{
  const mpm::RigidHold& hold = solver.projectile_hold();
  const mpm::RigidHoldRecord& r = hold.record();
  if (!r.considered())
    return {};
  const std::string name = solver.scene().bodies[solver.projectile()].name;
  std::ostringstream o;
  o << std::setprecision(3) << "  projectile " << name;
  if (!r.held)
  {
    o << " deformable from the start (Time/Rigid projectile while elastic): " << r.reason;
    return o.str();
  }
  o << " held rigid while elastic: acoustic impact pressure " << r.impact_pressure / 1e6
    << " MPa against the limit " << hold.pressure_limit() / 1e6
    << " MPa (Time/Rigid projectile stress limit of its yield stress); it turns deformable at "
       "the first step whose contact pressure exceeds the limit or whose contact moment would "
       "turn it by more than "
    << hold.drift_limit() * 1e3 << " mm at its farthest point";
  return o.str();
}

std::string rigid_hold_release_event(const mpm::Solver& solver, bool& reported)
{
  const mpm::RigidHoldRecord& r = solver.projectile_hold().record();
  if (reported || r.release_step < 0)
    return {};
  reported = true;
  std::ostringstream o;
  o << std::setprecision(4) << "projectile " << solver.scene().bodies[solver.projectile()].name
    << " turns deformable after step " << r.release_step << " (t = " << r.release_time
    << " s): " << r.reason
    << (solver.subcycles_projectile() ? "; subcycled from here on" : "");
  return o.str();
}

std::string rigid_hold_final_note(const mpm::Solver& solver)
{
  const mpm::RigidHold& hold = solver.projectile_hold();
  const mpm::RigidHoldRecord& r = hold.record();
  if (!r.held && r.release_step < 0)
    return {};
  std::ostringstream o;
  o << std::setprecision(3) << "projectile held rigid while elastic"
    << (r.held ? " to the end" : " until step " + std::to_string(r.release_step))
    << ": peak contact pressure " << r.peak_pressure / 1e6 << " MPa at t = " << r.peak_pressure_time
    << " s (limit " << hold.pressure_limit() / 1e6 << " MPa), rotation neglected "
    << r.rotation_drift * 1e3 << " mm at its farthest point (limit " << hold.drift_limit() * 1e3
    << " mm)";
  return o.str();
}
} // namespace vulnus::simulator
