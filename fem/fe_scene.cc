// Driver of a pure FE scene: time loop, output schedule, CSV history and progress log.
#include "fem/fe_scene.h"

#include "fem/far_field_solver.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>

namespace vulnus::fem
{
namespace
{
void write_history_line(std::ostream& csv, const FeDiagnostics& d, const double dt)
{
  csv << d.time << ',' << d.step << ',' << dt << ',' << d.kinetic_energy << ',' << d.strain_energy
      << ',' << d.external_work << ',' << d.dissipated_energy << ',' << d.momentum[0] << ','
      << d.momentum[1] << ',' << d.momentum[2] << ',' << d.n_failed_points << '\n';
}
} // namespace

FeSceneResult run_fe_scene(const FeSceneParameters& parameters, const std::string& output_dir,
                           std::ostream& log, const MPI_Comm communicator)
{
  const auto start = std::chrono::steady_clock::now();
  const bool root = dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
  FarFieldSolver solver(parameters, communicator);
  solver.setup();

  FeSceneResult result;
  result.n_cells = solver.n_active_cells();
  result.n_dofs = solver.n_dofs();
  std::ofstream csv;
  if (root)
  {
    std::filesystem::create_directories(output_dir);
    csv.open(output_dir + "/fe_history.csv");
    csv << std::setprecision(10)
        << "time,step,dt,kinetic_energy,strain_energy,external_work,dissipated_energy,"
           "momentum_x,momentum_y,momentum_z,failed_points\n";
    log << "FE scene: " << result.n_cells << " cells, " << result.n_dofs << " dofs, "
        << solver.n_quadrature_points() << " quadrature points, Q" << parameters.degree << ", "
        << dealii::Utilities::MPI::n_mpi_processes(communicator) << " MPI rank(s)\n";
  }
  solver.write_output(output_dir);
  result.n_outputs = 1;
  const FeDiagnostics initial = solver.diagnostics(); // collective
  if (root)
    write_history_line(csv, initial, 0.0);

  const double end = parameters.end_time;
  double next_output = parameters.output_interval > 0.0 ? parameters.output_interval : end;
  double dt = 0.0;
  while (solver.time() < end * (1.0 - 1e-12))
  {
    dt = std::min(solver.next_time_step(), end - solver.time());
    solver.advance(dt);
    const bool last = solver.time() >= end * (1.0 - 1e-12);
    const bool logged = parameters.log_interval > 0 &&
                        (solver.step_number() % parameters.log_interval == 0 || last);
    if (logged)
    {
      const FeDiagnostics d = solver.diagnostics();
      if (root)
      {
        write_history_line(csv, d, dt);
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        log << "FE step " << d.step << "  t = " << d.time << " s  dt = " << dt
            << " s  E_kin = " << d.kinetic_energy << " J  E_strain = " << d.strain_energy
            << " J  failed points = " << d.n_failed_points << "  wall " << elapsed << " s  left ~"
            << elapsed * (end - d.time) / std::max(d.time, 1e-300) << " s\n";
      }
    }
    if (solver.time() >= next_output * (1.0 - 1e-12) || last)
    {
      solver.write_output(output_dir);
      ++result.n_outputs;
      while (next_output <= solver.time() * (1.0 + 1e-12))
        next_output += parameters.output_interval > 0.0 ? parameters.output_interval : end;
    }
  }

  const FeDiagnostics d = solver.diagnostics();
  result.n_steps = solver.step_number();
  result.time = solver.time();
  result.kinetic_energy = d.kinetic_energy;
  result.strain_energy = d.strain_energy;
  result.external_work = d.external_work;
  result.dissipated_energy = d.dissipated_energy;
  result.n_failed_points = d.n_failed_points;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (root)
  {
    log << "FE scene done: " << result.n_steps << " steps to t = " << result.time << " s in "
        << result.wall_seconds << " s\n";
    if (result.n_failed_points > 0)
      log << "*** WARNING: " << result.n_failed_points
          << " FE quadrature points failed: failure reached the FE far field; enlarge the MPM "
             "zone ***\n";
  }
  return result;
}
} // namespace vulnus::fem
