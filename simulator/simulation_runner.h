// The simulation driver behind `vulnus run`: picks the stepper the deck asks for (pure MPM,
// hybrid MPM-FE or pure FE), starts MPI where it is needed and runs the one time loop.
#pragma once

#include "deck/run_parameters.h"
#include "io/run_directory.h"

namespace vulnus::simulator
{
/// Runs the scene, writing outputs into `directory`; returns the exit status of simulate().
int run_simulation(const deck::RunParameters& parameters, io::RunDirectory& directory);
} // namespace vulnus::simulator
