// Rows of the hybrid CSV history.
#include "simulator/hybrid_history.h"

#include "simulator/mpm_history.h"

#include "analysis/mpm_summary.h"

#include <algorithm>

namespace vulnus::simulator
{
double hybrid_scene_energy(const coupling::HybridSolver& solver, const mpm::SceneDiagnostics& m,
                           const fem::FeDiagnostics& f)
{
  // The adaptive zone's conversions change the energy by what they record (kept apart, so the
  // balance tests the time stepping).
  return analysis::accounted_energy(solver.mpm(), m) + f.kinetic_energy + f.strain_energy +
         f.dissipated_energy - solver.conversion_energy_change();
}

std::vector<std::string> hybrid_history_columns()
{
  std::vector<std::string> columns = mpm_history_columns();
  for (const char* name :
       {"fe_steps", "fe_kinetic_energy", "fe_strain_energy", "fe_dissipated_energy",
        "fe_failed_points", "scene_energy", "scene_balance_error", "scene_momentum_x",
        "scene_momentum_y", "scene_momentum_z", "interface_mpm_work", "interface_fe_work",
        "interface_energy_error", "zone_volume", "converted_volume",
        "conversion_energy_change"})
    columns.push_back(name);
  return columns;
}

std::vector<double> hybrid_history_row(const coupling::HybridSolver& solver,
                                       const double initial_energy)
{
  const mpm::SceneDiagnostics m = solver.mpm().diagnostics();
  const fem::FeDiagnostics f = solver.fe().diagnostics();
  std::vector<double> row = mpm_history_row(solver.mpm(), m);
  // The target and the supports are the whole scene's: the far field's share added.
  static const std::vector<std::string> columns = mpm_history_columns();
  auto column = [](const char* name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  static const std::size_t target_kinetic = column("target_kinetic_J"),
                           target_momentum = column("target_momentum_x"),
                           first_support = column("support_impulse_x-");
  row[target_kinetic] += f.kinetic_energy;
  for (unsigned int d = 0; d < 3; ++d)
    row[target_momentum + d] += f.momentum[d];
  for (unsigned int face = 0; face < fem::n_slab_faces; ++face)
    row[first_support + face] += f.support_impulses[face][face / 2];
  const double energy = hybrid_scene_energy(solver, m, f);
  const coupling::InterfaceLedger& ledger = solver.ledger();
  const Eigen::Vector3d momentum = m.momentum + Eigen::Vector3d(f.momentum[0], f.momentum[1], f.momentum[2]);
  for (const double value :
       {double(ledger.fe_steps), f.kinetic_energy, f.strain_energy, f.dissipated_energy,
        double(f.n_failed_points), energy,
        analysis::relative_balance_error(energy, initial_energy), momentum[0],
        momentum[1], momentum[2], ledger.mpm_work, ledger.fe_work, ledger.energy_error()})
    row.push_back(value);
  double zone_volume = 1.0;
  for (int d = 0; d < 3; ++d)
    zone_volume *= solver.zone_max()[d] - solver.zone_min()[d];
  row.push_back(zone_volume);
  row.push_back(solver.converted_volume());
  row.push_back(solver.conversion_energy_change());
  return row;
}
} // namespace vulnus::simulator
