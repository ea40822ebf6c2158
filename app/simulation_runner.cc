// The simulation driver behind `vulnus run`: picks the scene type from the deck (pure MPM
// for now; the hybrid MPM-FE scheme plugs in here) and runs it.
#include "app/simulation_runner.h"

#include "app/mpm_run.h"

namespace vulnus::app
{
int run_simulation(const RunParameters& parameters, RunDirectory& directory)
{
  return run_mpm_scene(parameters, directory);
}
} // namespace vulnus::app
