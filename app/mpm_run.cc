// Pure-MPM time loop with its outputs.
#include "app/mpm_run.h"

#include "app/mpm_run_files.h"
#include "app/mpm_summary.h"
#include "app/stop_signals.h"
#include "app/summary_json.h"
#include "mpm/solver.h"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace vulnus::app
{
namespace
{
std::string format_seconds(const double s)
{
  std::ostringstream o;
  if (s < 120)
    o << std::fixed << std::setprecision(0) << s << " s";
  else
    o << std::fixed << std::setprecision(1) << s / 60 << " min";
  return o.str();
}

/// Collective: point counts are summed over the ranks.
void log_scene(const mpm::Solver& solver, RunDirectory& directory)
{
  const mpm::SceneParameters& scene = solver.scene();
  const mpm::Particles& p = solver.points();
  std::vector<std::uint64_t> body_points(p.n_bodies());
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
    body_points[b] = p.end_of(b) - p.begin_of(b);
  solver.rank_group().sum(body_points.data(), static_cast<int>(body_points.size()));
  std::ostringstream o;
  o << "MPM scene: " << solver.n_points_all_ranks() << " points, cell size " << scene.cell_size << " m, grid "
    << solver.background_grid().cells()[0] << " x " << solver.background_grid().cells()[1]
    << " x " << solver.background_grid().cells()[2] << " cells, "
    << (scene.shape_function == mpm::ShapeFunction::linear ? "linear" : "GIMP")
    << " shape functions, " << (scene.update_scheme == mpm::UpdateScheme::musl ? "MUSL" : "USL")
    << ", " << omp_get_max_threads() << " thread(s)";
  if (solver.rank_group().distributed())
  {
    o << " on each of " << solver.rank_group().size() << " ranks; slabs along axis "
      << solver.slabs().axis() << " from cell layers";
    for (int r = 1; r < solver.rank_group().size(); ++r)
      o << ' ' << solver.slabs().first_layers()[r];
    o << ", re-cut to balance the points every " << scene.sort_interval << " steps";
  }
  directory.log(o.str());
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
  {
    const mpm::BodyParameters& body = scene.bodies[b];
    const materials::Material& m = solver.body_material(b);
    std::ostringstream line;
    line << "  body " << body.name << ": " << body_points[b] << " points, material "
         << body.material << " (" << m.model_name() << ")";
    if (m.is_rigid())
      line << ", rigid: no stress update, no time-step limit";
    else if (m.model_name().find("hyperelastic") != std::string::npos)
    {
      const bool failure_on =
        mpm::find_material(scene, body.material)->parameters.tissue.failure.enabled;
      line << (m.uses_fibers() ? "" : ", no fiber work")
           << (failure_on
                 ? ", failed tissue keeps its pressure in compression"
                 : ", failure off: no eigenvalues");
    }
    directory.log(line.str());
  }
  std::ostringstream contact;
  contact << "  contact: ";
  if (solver.uses_contact() && scene.contact.enabled)
    contact << "multi-velocity field at nodes shared by bodies, friction "
            << scene.contact.friction_coefficient;
  else if (solver.uses_contact())
    contact << "disabled: the bodies share one velocity field (no-slip)";
  else
    contact << "none (one body): no contact pass";
  directory.log(contact.str());
}
void log_checkpoint_policy(const OutputParameters& output, RunDirectory& directory)
{
  std::ostringstream o;
  o << "checkpoints: ";
  if (output.checkpoint_step_interval > 0)
    o << "every " << output.checkpoint_step_interval << " steps, ";
  if (output.checkpoint_wall_interval > 0)
    o << "every " << output.checkpoint_wall_interval << " s of wall time, ";
  o << "on SIGINT/SIGTERM; newest " << output.checkpoints_kept << " kept in "
    << directory.file("checkpoints");
  directory.log(o.str());
}
} // namespace

int run_mpm_scene(const RunParameters& parameters, RunDirectory& directory,
                  const MPI_Comm communicator)
{
  if (parameters.scene.n_threads > 0)
    omp_set_num_threads(static_cast<int>(parameters.scene.n_threads));
  install_stop_signal_handlers();
  const auto wall_start = std::chrono::steady_clock::now();
  auto wall_seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };

  mpm::Solver solver(parameters.scene, communicator);
  const mpm::RankGroup& ranks = solver.rank_group();
  log_scene(solver, directory);
  const std::size_t n_points_at_start = solver.n_points_all_ranks();

  RunTotals totals;
  const mpm::SceneDiagnostics initial = solver.diagnostics();
  if (solver.projectile() >= 0) // from the initial state, before any restart
  {
    const mpm::BodySummary b = initial.bodies[solver.projectile()];
    totals.projectile_initial_speed = b.velocity.dot(solver.flight_direction());
    totals.projectile_initial_kinetic_energy = b.kinetic_energy;
  }

  // benchmarks/README.md, stability: the paper scene's energy balance error passes 5 % from
  // CFL 0.6 with the elastic-plastic bullet (1.3 % at the default 0.4).
  constexpr double largest_tested_cfl = 0.5;
  if (parameters.scene.cfl > largest_tested_cfl)
  {
    std::ostringstream message;
    message << "Time/CFL = " << parameters.scene.cfl << " is above " << largest_tested_cfl
            << ": in the stability sweep (benchmarks/README.md) the paper scene gains more than "
               "5 % energy from CFL 0.6 on; check energy.balance_error or use 0.4";
    directory.warn(message.str());
    totals.warnings.push_back(message.str());
  }

  MpmRunFiles files(parameters, directory, ranks);
  files.start(solver);
  log_checkpoint_policy(parameters.output, directory);

  double last_progress = 0.0;
  int stop_signal = 0;
  while (!solver.finished())
  {
    // Ranks may see a signal at different steps: stop together on the first one seen.
    if ((stop_signal = static_cast<int>(ranks.max(pending_stop_signal()))) != 0)
    {
      const std::string path = files.write_checkpoint(solver, wall_seconds());
      directory.warn(std::string("stopped by ") + stop_signal_name(stop_signal) + " at step " +
                     std::to_string(solver.step_count()) + "; checkpoint " + path +
                     "; continue with `vulnus run DECK --restart " + directory.path() + "`");
      return 128 + stop_signal;
    }
    try
    {
      solver.advance();
    }
    catch (const mpm::BlowUp& e)
    {
      totals.completed = false;
      totals.error = e.what();
      directory.warn(std::string("blow-up: ") + e.what());
      directory.warn("the last good state is " + files.last_good_state());
      break;
    }
    files.after_step(solver);
    const double wall = ranks.max(wall_seconds()); // the same on every rank
    if (files.checkpoint_due(solver, wall))
      directory.log("checkpoint: " + files.write_checkpoint(solver, wall));
    if (wall - last_progress >= 5.0)
    {
      last_progress = wall;
      const double rate = solver.time() / wall; // simulated seconds per wall second
      std::ostringstream o;
      o << "t = " << std::scientific << std::setprecision(3) << solver.time() << " s, step "
        << solver.step_count() << ", dt = " << solver.last_time_step() << " s, "
        << n_points_at_start - solver.removed_points() << " points, time left <= "
        << format_seconds((parameters.scene.end_time - solver.time()) / rate);
      directory.log(o.str());
    }
  }
  totals.wall_seconds = files.earlier_wall_seconds() + wall_seconds();
  if (totals.completed)
    files.finish(solver);

  if (solver.projectile() >= 0 && !solver.body_material(solver.projectile()).is_rigid())
  {
    const double ratio = solver.peak_von_mises_over_yield()[solver.projectile()];
    if (ratio > 0.0 && ratio < 0.5)
      totals.warnings.push_back("the projectile stayed far below yield (max von Mises / yield = " +
                                std::to_string(ratio) +
                                "): a rigid projectile (Model = rigid) gives the same wound at a "
                                "much larger time step");
  }
  if (solver.removed_points() > 0)
    totals.warnings.push_back(std::to_string(solver.removed_points()) +
                              " points left the grid and were removed; their energy is booked "
                              "as outflow");
  for (const std::string& w : totals.warnings)
    directory.warn(w);

  const WoundSample wound = collect_wound_sample(solver); // failed points only, on rank 0
  const mpm::SceneDiagnostics final_state = solver.diagnostics();
  totals.mpi_bytes_sent = ranks.sum(ranks.bytes_sent());
  if (!directory.writes_files())
    return totals.completed ? 0 : 1;
  const nlohmann::json summary = mpm_summary(solver, totals, wound, final_state);
  write_summary_json(directory.file("summary.json"), summary);

  const mpm::PhaseTimes& t = solver.phase_times();
  std::ostringstream o;
  o << std::setprecision(4) << "done: " << solver.step_count() << " steps to t = " << solver.time()
    << " s in " << totals.wall_seconds << " s wall, "
    << summary["particle_steps_per_second"].get<double>() << " point-steps/s; phases (s): "
    << "time step " << t.time_step << ", particle-to-grid " << t.particle_to_grid
    << ", grid update " << t.grid_update << ", contact " << t.contact << ", grid-to-particle " << t.grid_to_particle
    << ", stress " << t.stress_update << ", checks " << t.checks_and_sorting;
  directory.log(o.str());
  std::ostringstream e;
  e << std::setprecision(4) << "energy balance error " << summary["energy"]["balance_error"].get<double>()
    << "; failed points: matrix " << summary["failed"]["matrix"] << ", fiber "
    << summary["failed"]["fiber"] << ", total " << summary["failed"]["total"];
  if (solver.projectile() >= 0)
    e << "; bullet exit velocity " << summary["bullet"]["exit_velocity_m_s"].get<double>() << " m/s";
  directory.log(e.str());
  return totals.completed ? 0 : 1;
}
} // namespace vulnus::app
