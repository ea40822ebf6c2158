// The note and the guard of a zone that ends along the projectile's path.
#include "simulator/zone_end_guard.h"

#include "core/run_failure.h"
#include "coupling/decomposition.h"

#include <sstream>

namespace vulnus::simulator
{
namespace
{
const char* zone_entry(const coupling::ZoneEnd& end)
{
  return end.upper ? "Hybrid/Zone max" : "Hybrid/Zone min";
}

/// The split body's face on the end's axis and side, m.
double body_face(const coupling::HybridScene& split, const coupling::ZoneEnd& end)
{
  return end.upper ? split.fe.slab_max[end.axis] : split.fe.slab_min[end.axis];
}

} // namespace

std::string zone_end_note(const coupling::HybridScene& split)
{
  const coupling::ZoneEnd end =
      coupling::zone_end_along_path(split, split.hybrid.zone_min, split.hybrid.zone_max);
  if (!end.ends)
    return {};
  std::string projectile;
  for (const mpm::BodyParameters& body : split.mpm.bodies)
    if (body.is_projectile)
      projectile = body.name;
  const double margin = coupling::zone_end_margin_cells * split.mpm.cell_size;
  const char* const axis = coupling::axis_name(end.axis);
  std::ostringstream o;
  o << "the MPM zone ends at " << axis << " = " << end.coordinate
    << " m along the path of projectile '" << projectile << "', inside body '"
    << split.mpm.bodies[split.coupled_body].name << "' (its face at " << axis << " = "
    << body_face(split, end) << " m); beyond it the tissue is finite elements, so the run "
    << "stops, as a failure, if the projectile comes within its radius plus "
    << coupling::zone_end_margin_cells << " cells of that end (its front within " << margin
    << " m)";
  if (split.hybrid.adaptive.enabled)
  {
    const double limit = end.upper ? split.limit_max[end.axis] : split.limit_min[end.axis];
    o << "; the adaptive zone may grow to " << axis << " = " << limit
      << " m, and the stop follows the zone's end as it grows";
  }
  o << "; lengthen " << zone_entry(end) << " along the path if the projectile may go deeper";
  return o.str();
}

std::string zone_end_note(const deck::RunParameters& parameters)
{
  if (parameters.method != deck::Method::mpm || !parameters.hybrid.enabled)
    return {};
  return zone_end_note(
      coupling::decompose(parameters.scene, parameters.hybrid, parameters.far_field));
}

void check_zone_end(const coupling::HybridSolver& solver)
{
  const mpm::Solver& mpm_side = solver.mpm();
  const int b = mpm_side.projectile();
  if (b < 0 || solver.far_field_retired())
    return;
  const coupling::HybridScene& split = solver.scene();
  const coupling::ZoneEnd end =
      coupling::zone_end_along_path(split, solver.zone_min(), solver.zone_max());
  if (!end.ends) // the same on every rank: the zone is
    return;
  // The nose along the flight, as x . flight (the same on every rank: the record is reduced).
  const double nose =
      mpm_side.penetration().latest().depth + mpm_side.target_extent_along_flight().first;
  const double margin = coupling::zone_end_margin_cells * split.mpm.cell_size;
  if (nose + margin <= end.along)
    return;
  const char* const axis = coupling::axis_name(end.axis);
  std::ostringstream problem, cause, remedy;
  problem << "projectile '" << split.mpm.bodies[static_cast<std::size_t>(b)].name
          << "', its front at " << nose << " m along its flight, came within "
          << coupling::zone_end_margin_cells << " cells (" << margin
          << " m) of the MPM zone's end at " << axis << " = " << end.coordinate
          << " m along its path";
  cause << "the zone ends inside body '" << split.mpm.bodies[split.coupled_body].name
        << "' (its face at " << axis << " = " << body_face(split, end)
        << " m), and beyond it the tissue is finite elements, which the projectile cannot enter";
  remedy << "lengthen " << zone_entry(end) << " along the path (" << axis << " = " << end.coordinate
         << " m now), past where the projectile stops";
  throw BlowUp(RunFailure{problem.str(), cause.str(), remedy.str()});
}
} // namespace vulnus::simulator
