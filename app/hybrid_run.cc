// Hybrid MPM-FE time loop with its outputs. Under mpirun every rank runs it (the MPM zone in
// slabs, the FE far field in deal.II's partition); rank 0 writes the log, history and summary,
// all ranks write their points into one particle file per output time.
#include "app/hybrid_run.h"

#include "app/csv_history.h"
#include "app/hybrid_history.h"
#include "app/mpm_snapshot.h"
#include "app/mpm_summary.h"
#include "app/particle_output.h"
#include "app/summary_json.h"

#include <omp.h>

#include <chrono>
#include <memory>
#include <iomanip>
#include <sstream>

namespace vulnus::app
{
namespace
{
const char* scheme_name(const coupling::CouplingScheme s)
{
  return s == coupling::CouplingScheme::same_step ? "same step" : "multi step";
}

const char* integrator_name(const fem::TimeIntegrator i)
{
  switch (i)
  {
  case fem::TimeIntegrator::central_difference:
    return "explicit central difference";
  case fem::TimeIntegrator::newmark:
    return "implicit Newmark";
  case fem::TimeIntegrator::generalized_alpha:
    return "implicit generalized alpha";
  }
  return "?";
}

/// Collective.
void log_scene(const coupling::HybridSolver& solver, RunDirectory& directory)
{
  const coupling::HybridScene& split = solver.scene();
  const std::size_t n_points = solver.mpm().n_points_all_ranks();
  std::ostringstream o;
  o << "hybrid scene: MPM zone (" << split.hybrid.zone_min[0] << ", " << split.hybrid.zone_min[1]
    << ", " << split.hybrid.zone_min[2] << ") to (" << split.hybrid.zone_max[0] << ", "
    << split.hybrid.zone_max[1] << ", " << split.hybrid.zone_max[2] << ") m: "
    << n_points << " points; FE far field: " << solver.fe().n_active_cells()
    << " cells, " << solver.fe().n_dofs() << " dofs, " << integrator_name(split.fe.integrator)
    << "; " << solver.n_interface_nodes() << " shared interface nodes, scheme "
    << scheme_name(split.hybrid.scheme) << ", " << omp_get_max_threads() << " thread(s)";
  const mpm::RankGroup& ranks = solver.mpm().rank_group();
  if (ranks.distributed())
    o << " on each of " << ranks.size() << " MPI ranks (MPM zone in slabs along axis "
      << solver.mpm().slabs().axis() << ", FE cells by deal.II's partition; "
      << solver.n_interface_nodes_across_ranks()
      << " interface nodes have their FE owner and MPM slab on different ranks)";
  directory.log(o.str());
}
} // namespace

int run_hybrid_scene(const RunParameters& parameters, RunDirectory& directory)
{
  if (parameters.scene.n_threads > 0)
    omp_set_num_threads(static_cast<int>(parameters.scene.n_threads));
  const auto wall_start = std::chrono::steady_clock::now();
  auto wall_seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };

  const coupling::HybridScene split =
    coupling::decompose(parameters.scene, parameters.hybrid, parameters.far_field);
  coupling::HybridSolver solver(split, MPI_COMM_WORLD);
  log_scene(solver, directory);
  const mpm::Solver& mpm_side = solver.mpm();

  RunTotals totals;
  if (mpm_side.projectile() >= 0)
  {
    const mpm::BodySummary b = mpm_side.diagnostics().bodies[mpm_side.projectile()];
    totals.projectile_initial_speed = b.velocity.dot(mpm_side.flight_direction());
    totals.projectile_initial_kinetic_energy = b.kinetic_energy;
  }
  const double initial_energy = hybrid_scene_energy(solver, mpm_side.diagnostics(),
                                                    solver.fe().diagnostics());

  const mpm::RankGroup& ranks = mpm_side.rank_group();
  std::unique_ptr<CsvHistory> history; // rank 0
  if (directory.writes_files())
    history = std::make_unique<CsvHistory>(directory.file("history.csv"), hybrid_history_columns());
  auto add_history_row = [&] {
    const std::vector<double> row = hybrid_history_row(solver, initial_energy); // collective
    if (history)
      history->add_row(row);
  };
  ParticleOutput output(directory.path(), "particles", ranks.communicator());
  const double output_interval = parameters.output.particle_interval;
  auto write_outputs = [&] {
    output.write(solver.time(), mpm_snapshot(mpm_side));
    solver.fe().write_output(directory.path());
  };
  write_outputs();
  double next_output = output_interval > 0 ? output_interval : parameters.scene.end_time * 2;
  add_history_row();

  double last_progress = 0.0;
  while (!solver.finished())
  {
    try
    {
      solver.advance();
    }
    catch (const std::runtime_error& e) // mpm::BlowUp, or an inverted FE element
    {
      totals.completed = false;
      totals.error = e.what();
      directory.warn(std::string("blow-up: ") + e.what());
      directory.warn("the last good state is the last output (t = " +
                     std::to_string(next_output - output_interval) + " s) in " +
                     output.xdmf_path() + " and fe_mesh.xdmf");
      break;
    }
    if (mpm_side.step_count() % parameters.output.history_interval == 0)
      add_history_row();
    if (solver.time() >= next_output * (1 - 1e-12))
    {
      write_outputs();
      next_output += output_interval;
    }
    const double wall = ranks.max(wall_seconds()); // the same on every rank
    if (wall - last_progress >= 5.0)
    {
      last_progress = wall;
      std::ostringstream o;
      o << "t = " << std::scientific << std::setprecision(3) << solver.time() << " s, MPM step "
        << mpm_side.step_count() << " (dt = " << mpm_side.last_time_step() << " s), FE step "
        << solver.ledger().fe_steps << ", interface energy error "
        << solver.ledger().energy_error() << " J";
      directory.log(o.str());
    }
  }
  totals.wall_seconds = wall_seconds();
  if (totals.completed)
  {
    add_history_row();
    if (!output.has_output_at(solver.time()))
      write_outputs();
  }
  if (history)
    history->flush();

  const fem::FeDiagnostics fe = solver.fe().diagnostics();
  if (fe.n_failed_points > 0)
    totals.warnings.push_back(
      "*** " + std::to_string(fe.n_failed_points) +
      " FE quadrature points failed: the wound reached the far field; enlarge Hybrid/Zone min "
      "and Zone max");
  if (mpm_side.removed_points() > 0)
    totals.warnings.push_back(std::to_string(mpm_side.removed_points()) +
                              " points left the grid and were removed; their energy is booked "
                              "as outflow");
  for (const std::string& w : totals.warnings)
    directory.warn(w);

  const WoundSample wound = collect_wound_sample(mpm_side); // failed points only, on rank 0
  const mpm::SceneDiagnostics m = mpm_side.diagnostics();
  totals.mpi_bytes_sent = ranks.sum(ranks.bytes_sent());
  if (!directory.writes_files())
    return totals.completed ? 0 : 1;
  nlohmann::json summary = mpm_summary(mpm_side, totals, wound, m);
  const double energy = hybrid_scene_energy(solver, m, fe);
  const coupling::InterfaceLedger& ledger = solver.ledger();
  summary["method"] = "hybrid";
  summary["fe_cells"] = solver.fe().n_active_cells();
  summary["fe_failed_points"] = fe.n_failed_points;
  summary["energy"]["initial_J"] = initial_energy;
  summary["energy"]["kinetic_J"] = m.kinetic_energy + fe.kinetic_energy;
  summary["energy"]["strain_J"] = m.strain_energy + fe.strain_energy;
  summary["energy"]["dissipated_J"] =
    m.dissipated_energy + mpm_side.contact_dissipation() + fe.dissipated_energy;
  summary["energy"]["balance_error"] =
    initial_energy > 0 ? (energy - initial_energy) / initial_energy : 0.0;
  summary["hybrid"] = {{"scheme", scheme_name(split.hybrid.scheme)},
                       {"fe_integrator", integrator_name(split.fe.integrator)},
                       {"mpm_steps", ledger.mpm_steps},
                       {"fe_steps", ledger.fe_steps},
                       {"interface_nodes", solver.n_interface_nodes()},
                       {"interface_nodes_across_ranks", solver.n_interface_nodes_across_ranks()},
                       {"fe_dofs", solver.fe().n_dofs()},
                       {"interface_mpm_work_J", ledger.mpm_work},
                       {"interface_fe_work_J", ledger.fe_work},
                       {"interface_energy_error_J", ledger.energy_error()},
                       {"mpm_seconds", mpm_side.phase_times().total() - mpm_side.phase_times().coupling},
                       {"coupling_and_fe_seconds", mpm_side.phase_times().coupling}};
  write_summary_json(directory.file("summary.json"), summary);

  std::ostringstream o;
  o << std::setprecision(4) << "done: " << mpm_side.step_count() << " MPM steps and "
    << ledger.fe_steps << " FE steps to t = " << solver.time() << " s in " << totals.wall_seconds
    << " s wall (MPM " << summary["hybrid"]["mpm_seconds"].get<double>() << " s, FE and coupling "
    << mpm_side.phase_times().coupling << " s); energy balance error "
    << summary["energy"]["balance_error"].get<double>() << ", interface energy error "
    << ledger.energy_error() << " J; failed points: matrix " << summary["failed"]["matrix"]
    << ", fiber " << summary["failed"]["fiber"] << ", total " << summary["failed"]["total"];
  if (mpm_side.projectile() >= 0)
    o << "; bullet exit velocity " << summary["bullet"]["exit_velocity_m_s"].get<double>() << " m/s";
  directory.log(o.str());
  return totals.completed ? 0 : 1;
}
} // namespace vulnus::app
