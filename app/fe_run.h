// A pure finite element scene (Scene/Method = FE): runs the far-field solver on the one box
// body with the deck's face supports and load, writes fe_mesh.xdmf, fe_history.csv and
// summary.json into the run directory.
#pragma once

#include "app/run_directory.h"
#include "app/run_parameters.h"

namespace vulnus::app
{
/// Returns the exit status: 0 when the run completed, 1 when the solution broke down.
int run_fe_scene(const RunParameters& parameters, RunDirectory& directory);
} // namespace vulnus::app
