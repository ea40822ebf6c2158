// The simulation driver behind `vulnus run`: picks the scene type from the deck (pure MPM,
// hybrid MPM-FE, or pure FE) and runs it. MPI is started only for the scenes with FE.
#include "app/simulation_runner.h"

#include "app/fe_run.h"
#include "app/hybrid_run.h"
#include "app/mpm_run.h"

#include <deal.II/base/mpi.h>

namespace vulnus::app
{
int run_simulation(const RunParameters& parameters, RunDirectory& directory)
{
  if (parameters.method == Method::mpm && !parameters.hybrid.enabled)
  {
    directory.log("method: pure MPM (no FE region: no mesh, no MPI)");
    return run_mpm_scene(parameters, directory);
  }
  int argc = 0;
  char** argv = nullptr;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (parameters.method == Method::fe)
  {
    directory.log("method: pure finite elements");
    return run_fe_scene(parameters, directory);
  }
  directory.log("method: hybrid, MPM zone coupled to an FE far field");
  return run_hybrid_scene(parameters, directory);
}
} // namespace vulnus::app
