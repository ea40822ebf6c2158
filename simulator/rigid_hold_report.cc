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
  if (solver.scene().contact.exact_rigid_surface)
    o << "; its contact takes its points from here on, not the exact surface (Contact/Rigid "
         "surface = exact is a rigid body's)";
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

std::string rigid_hold_surface_warning(const mpm::Solver& solver)
{
  const mpm::RigidHoldRecord& r = solver.projectile_hold().record();
  if (!solver.scene().contact.exact_rigid_surface || !r.considered() || r.held)
    return {};
  const std::string name = solver.scene().bodies[solver.projectile()].name;
  std::ostringstream o;
  o << std::setprecision(4) << "Contact/Rigid surface = exact: projectile '" << name << "' ";
  if (r.release_step >= 0)
    o << "took the exact surface only while held rigid while elastic, up to step "
      << r.release_step << " (t = " << r.release_time
      << " s); from there its contact took its points (as Rigid surface = points), and its "
         "velocity can jump at the switch";
  else
    o << "never took the exact surface: it was deformable from the start (" << r.reason
      << ") and its contact took its points";
  o << "; 'Material " << solver.scene().bodies[solver.projectile()].material
    << "/Model = rigid' keeps the exact surface throughout, Time/Rigid projectile while "
       "elastic = false the points";
  return o.str();
}

std::string rigid_rotation_event(const mpm::Solver& solver, bool& reported)
{
  const mpm::NeglectedRotation& rotation = solver.projectile_rotation();
  if (reported || rotation.exceeded_step() < 0)
    return {};
  reported = true;
  std::ostringstream o;
  o << std::setprecision(3) << "projectile " << solver.scene().bodies[solver.projectile()].name
    << " (rigid, it only translates): after step " << rotation.exceeded_step() << " (t = "
    << rotation.exceeded_time() << " s) its contact's moment would have turned it by "
    << rotation.angle() << " rad, moving its farthest point " << rotation.drift() * 1e3
    << " mm (limit " << rotation.drift_limit() * 1e3 << " mm)";
  return o.str();
}

std::string rigid_rotation_warning(const mpm::Solver& solver)
{
  const mpm::NeglectedRotation& rotation = solver.projectile_rotation();
  if (rotation.exceeded_step() < 0)
    return {};
  const mpm::BodyParameters& body = solver.scene().bodies[solver.projectile()];
  std::ostringstream o;
  o << std::setprecision(3) << "projectile '" << body.name
    << "' is rigid and only translates, but its contact's moment would have turned it by "
    << rotation.angle() << " rad over the run, moving its farthest point "
    << rotation.drift() * 1e3 << " mm (" << rotation.drift() / solver.scene().cell_size
    << " cells; limit " << mpm::NeglectedRotation::drift_cells << ", passed at step "
    << rotation.exceeded_step()
    << "): its path and wound are those of a projectile that cannot turn; a deformable law "
       "('Material "
    << body.material << "/Model = elastic plastic') lets it turn";
  return o.str();
}
} // namespace vulnus::simulator
