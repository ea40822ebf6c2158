// The simulation driver behind `vulnus run`.
#pragma once

#include "app/run_directory.h"
#include "app/run_parameters.h"

namespace vulnus::app
{
/// Run the scene, writing outputs into `directory`; returns the exit status (0 success,
/// 1 failure such as a detected blow-up).
int run_simulation(const RunParameters& parameters, RunDirectory& directory);
} // namespace vulnus::app
