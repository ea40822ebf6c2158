// The time loop of a pure-MPM scene: progress on the terminal, CSV history, particle output
// at the deck's interval, checkpoints (and restart), stop on SIGINT/SIGTERM, blow-up
// reporting, and summary.json at the end.
#pragma once

#include "app/run_directory.h"
#include "app/run_parameters.h"

#include <mpi.h>

namespace vulnus::app
{
/// Returns the exit status: 0 when the run completed, 1 after a detected blow-up, 128 + the
/// signal number when stopped by SIGINT/SIGTERM (after writing a checkpoint). With a
/// communicator of several ranks every rank calls it; rank 0 writes the log, history and
/// summary, all ranks write the particle output together and their own checkpoints.
int run_mpm_scene(const RunParameters& parameters, RunDirectory& directory, MPI_Comm communicator);
} // namespace vulnus::app
