// The time loop of a pure-MPM scene: progress on the terminal, CSV history, particle output
// at the deck's interval, checkpoints (and restart), stop on SIGINT/SIGTERM, blow-up
// reporting, and summary.json at the end.
#pragma once

#include "app/run_directory.h"
#include "app/run_parameters.h"

namespace vulnus::app
{
/// Returns the exit status: 0 when the run completed, 1 after a detected blow-up, 128 + the
/// signal number when stopped by SIGINT/SIGTERM (after writing a checkpoint).
int run_mpm_scene(const RunParameters& parameters, RunDirectory& directory);
} // namespace vulnus::app
