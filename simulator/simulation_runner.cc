// The stepper of a deck, and MPI for the runs that use it: the scenes with FE, and pure MPM
// started by mpirun on several processes.
#include "simulator/simulation_runner.h"

#include "io/mpi_launch.h"
#include "simulator/fe_stepper.h"
#include "simulator/hybrid_stepper.h"
#include "simulator/mpm_stepper.h"
#include "simulator/simulator.h"

#include <deal.II/base/mpi.h>

#include <omp.h>

namespace vulnus::simulator
{
int run_simulation(const deck::RunParameters& parameters, io::RunDirectory& directory)
{
  if (parameters.scene.n_threads > 0)
    omp_set_num_threads(static_cast<int>(parameters.scene.n_threads));
  const bool pure_mpm = parameters.method == deck::Method::mpm && !parameters.hybrid.enabled;
  if (pure_mpm && io::launcher_size() == 1)
  {
    directory.log("method: pure MPM (no FE region: no mesh, no MPI)");
    MpmStepper stepper(parameters, MPI_COMM_NULL);
    return simulate(stepper, parameters, directory);
  }
  int argc = 0;
  char** argv = nullptr;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  if (pure_mpm)
  {
    directory.log("method: pure MPM on " + std::to_string(n_ranks) +
                  " MPI ranks, one slab of the grid each");
    MpmStepper stepper(parameters, MPI_COMM_WORLD);
    return simulate(stepper, parameters, directory);
  }
  if (parameters.method == deck::Method::fe)
  {
    directory.log("method: pure finite elements on " + std::to_string(n_ranks) + " MPI rank(s)");
    FeStepper stepper(parameters, MPI_COMM_WORLD);
    return simulate(stepper, parameters, directory);
  }
  directory.log("method: hybrid, MPM zone coupled to an FE far field, on " +
                std::to_string(n_ranks) + " MPI rank(s)");
  HybridStepper stepper(parameters, MPI_COMM_WORLD);
  return simulate(stepper, parameters, directory);
}
} // namespace vulnus::simulator
