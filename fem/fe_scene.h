// A pure finite element scene: builds the far-field solver from FeSceneParameters, runs it
// to the end time with output, a CSV history and a progress log (what `vulnus run` calls
// for a deck with an FE section and no MPM).
#pragma once

#include "fem/fem_parameters.h"

#include <mpi.h>

#include <iosfwd>
#include <string>

namespace vulnus::fem
{
struct FeSceneResult
{
  unsigned int n_steps = 0;
  double time = 0.0;              ///< s, reached
  double kinetic_energy = 0.0;    ///< J, final
  double strain_energy = 0.0;     ///< J, final
  double external_work = 0.0;     ///< J, since t = 0
  double dissipated_energy = 0.0; ///< J, since t = 0
  unsigned long long n_failed_points = 0;
  unsigned long long n_cells = 0;
  unsigned long long n_dofs = 0;
  unsigned int n_outputs = 0;
  double wall_seconds = 0.0;
};

/// Runs the scene. Writes output_dir/fe_mesh.xdmf (+ fe_mesh_NNNNN.h5) at t = 0, every
/// output_interval and at the end, and output_dir/fe_history.csv (time, step, dt, energies,
/// momentum, failed points) every log_interval steps; logs progress and a loud failure
/// warning to `log` (rank 0 only). Throws std::invalid_argument for bad parameters and
/// std::runtime_error when the solution breaks down (inverted element, no convergence).
FeSceneResult run_fe_scene(const FeSceneParameters& parameters, const std::string& output_dir,
                           std::ostream& log, MPI_Comm communicator = MPI_COMM_WORLD);
} // namespace vulnus::fem
