// The simulation driver behind `vulnus run`: picks the scene type from the deck (pure MPM,
// hybrid MPM-FE, or pure FE) and runs it. MPI is started for the scenes with FE and for pure
// MPM started by mpirun on several processes.
#include "app/simulation_runner.h"

#include "app/fe_run.h"
#include "app/hybrid_run.h"
#include "app/mpm_run.h"
#include "app/mpi_launch.h"

#include <deal.II/base/mpi.h>

namespace vulnus::app
{
int run_simulation(const RunParameters& parameters, RunDirectory& directory)
{
  const bool pure_mpm = parameters.method == Method::mpm && !parameters.hybrid.enabled;
  if (pure_mpm && launcher_size() == 1)
  {
    directory.log("method: pure MPM (no FE region: no mesh, no MPI)");
    return run_mpm_scene(parameters, directory, MPI_COMM_NULL);
  }
  int argc = 0;
  char** argv = nullptr;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (pure_mpm)
  {
    directory.log("method: pure MPM on " +
                  std::to_string(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)) +
                  " MPI ranks, one slab of the grid each");
    return run_mpm_scene(parameters, directory, MPI_COMM_WORLD);
  }
  if (parameters.method == Method::fe)
  {
    directory.log("method: pure finite elements");
    return run_fe_scene(parameters, directory);
  }
  directory.log("method: hybrid, MPM zone coupled to an FE far field, on " +
                std::to_string(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)) +
                " MPI rank(s)");
  return run_hybrid_scene(parameters, directory);
}
} // namespace vulnus::app
