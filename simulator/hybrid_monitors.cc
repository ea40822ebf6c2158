// The hybrid run's validity monitors: interface displacement, MPM material outside the zone,
// interface energy error, failed far-field points.
#include "simulator/hybrid_monitors.h"

#include "mpm/binary_io.h"
#include "mpm/solver.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace vulnus::simulator
{
namespace
{
enum Monitor
{
  interface_displacement,
  mass_outside_zone,
  interface_energy_error,
  failed_fe_points
};

/// Largest FE interface-node displacement over the MPM cell size (the shared grid nodes stay
/// where they are while the FE nodes move).
double interface_displacement_over_cell(const coupling::HybridSolver& solver)
{
  double largest = 0.0;
  for (const fem::NodeRecord& node : solver.fe().interface_nodes())
    largest = std::max(largest, solver.fe().displacement(node).norm());
  largest = dealii::Utilities::MPI::max(largest, solver.fe().communicator());
  return largest / solver.scene().mpm.cell_size;
}

/// Mass fraction of the split body's points that moved more than half a cell out of the zone
/// into the far field's box (material the far field also holds; fragments beyond the slab's
/// faces are not). A following interface moves the zone's surface with it: its largest
/// displacement widens the margin.
double mass_fraction_outside_zone(const coupling::HybridSolver& solver,
                                  const double interface_displacement)
{
  const mpm::Solver& mpm_side = solver.mpm();
  const mpm::Particles& p = mpm_side.points();
  const coupling::HybridScene& split = solver.scene();
  const double margin =
    (0.5 + (solver.follows_interface() ? interface_displacement : 0.0)) * split.mpm.cell_size;
  double sums[2] = {0.0, 0.0};
  for (std::size_t i = p.begin_of(split.coupled_body); i < p.end_of(split.coupled_body); ++i)
  {
    sums[0] += p.mass[i];
    bool in_slab = true, in_zone = true;
    for (int d = 0; d < 3; ++d)
    {
      in_slab = in_slab && p.position[i][d] > split.fe.slab_min[d] &&
                p.position[i][d] < split.fe.slab_max[d];
      in_zone = in_zone && p.position[i][d] >= split.hybrid.zone_min[d] - margin &&
                p.position[i][d] <= split.hybrid.zone_max[d] + margin;
    }
    if (in_slab && !in_zone)
      sums[1] += p.mass[i];
  }
  mpm_side.rank_group().sum(sums, 2);
  return sums[0] > 0.0 ? sums[1] / sums[0] : 0.0;
}
} // namespace

HybridMonitors::HybridMonitors()
  : readings{{"interface_displacement_over_cell",
              "the FE interface nodes have moved far from the MPM grid nodes they share, so "
              "the coupling's small-displacement assumption fails",
              0.0, 0.25},
             {"mpm_mass_outside_zone_fraction",
              "MPM material has crossed into the far field, which also holds it",
              0.0, 0.01},
             {"interface_energy_error_over_initial",
              "the interface exchange creates or destroys energy (Hybrid/Scheme, Substeps)",
              0.0, 0.01},
             {"failed_fe_points",
              "the wound has reached the far field; enlarge Hybrid/Zone min and Zone max",
              0.0, 0.0}}
{
}

std::vector<std::string> HybridMonitors::check(const coupling::HybridSolver& solver,
                                               const double initial_energy, const bool all)
{
  if (all || solver.mpm().step_count() % check_interval == 0)
  {
    readings[interface_displacement].value = interface_displacement_over_cell(solver);
    // A following interface meets the grid wherever its nodes are: its motion has no bound.
    if (solver.follows_interface())
      readings[interface_displacement].bound = std::numeric_limits<double>::infinity();
    readings[mass_outside_zone].value =
      mass_fraction_outside_zone(solver, readings[interface_displacement].value);
    readings[interface_energy_error].value =
      initial_energy > 0.0 ? std::abs(solver.ledger().energy_error()) / initial_energy : 0.0;
  }
  readings[failed_fe_points].value = double(solver.fe().n_failed_points());

  std::vector<std::string> warnings;
  for (MonitorReading& r : readings)
  {
    r.peak = std::max(r.peak, r.value);
    if (r.warned || !(r.value > r.bound))
      continue;
    r.warned = true;
    std::ostringstream what;
    what << r.name << " = " << r.value << ", beyond " << r.bound << ": " << r.meaning;
    if (&r == &readings[failed_fe_points] && solver.scene().hybrid.stop_when_fe_points_fail)
      throw BlowUp(RunFailure{what.str() + " (stopped by Hybrid/Stop when FE points fail = true)",
                              "the wound reached the far field",
                              "enlarge Hybrid/Zone min and Zone max so the wound stays in the "
                              "MPM zone"});
    std::ostringstream o;
    o << "*** at step " << solver.mpm().step_count() << " (t = " << solver.time() << " s) "
      << what.str();
    warnings.push_back(o.str());
  }
  return warnings;
}

nlohmann::json HybridMonitors::summary() const
{
  nlohmann::json j;
  for (const MonitorReading& r : readings)
    j[r.name] = {{"peak", r.peak}, {"bound", r.bound}, {"exceeded", r.peak > r.bound}};
  return j;
}

void HybridMonitors::save(std::ostream& out) const
{
  for (const MonitorReading& r : readings)
  {
    mpm::binary::put(out, r.peak);
    mpm::binary::put(out, static_cast<std::uint8_t>(r.warned));
  }
}

void HybridMonitors::restore(std::istream& in)
{
  for (MonitorReading& r : readings)
  {
    std::uint8_t warned = 0;
    mpm::binary::get(in, r.peak);
    mpm::binary::get(in, warned);
    r.warned = warned != 0;
  }
}
} // namespace vulnus::simulator
