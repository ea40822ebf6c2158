// The one time loop of every run type (docs/DESIGN.md section 10): a stepper advances the
// scene; the postprocessors record it (history, particle and mesh series); checkpoints,
// stop signals, progress lines, failure reports and summary.json are handled here, the same
// way for pure MPM, hybrid and pure FE runs.
#pragma once

#include "deck/run_parameters.h"
#include "io/run_directory.h"
#include "simulator/stepper.h"

namespace vulnus::simulator
{
/// Runs `stepper` to its end. Returns the exit status: 0 when the run completed, 1 after a
/// blow-up or solver failure (the summary says which, and where the last good state is),
/// 128 + the signal number when stopped by SIGINT/SIGTERM (with a checkpoint when the
/// stepper can write one). Every rank of a distributed run calls it; rank 0 writes the log,
/// history and summary.
int simulate(Stepper& stepper, const deck::RunParameters& parameters, io::RunDirectory& directory);
} // namespace vulnus::simulator
