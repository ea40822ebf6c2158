// The time loop of a hybrid MPM-FE scene (Hybrid/Enabled): progress, CSV history with the
// interface energy ledger, particle and FE mesh output in the same run directory, blow-up
// reporting and summary.json (the pure-MPM keys plus the FE and coupling figures).
#pragma once

#include "app/run_directory.h"
#include "app/run_parameters.h"

namespace vulnus::app
{
/// Returns the exit status: 0 when the run completed, 1 after a blow-up or FE breakdown.
int run_hybrid_scene(const RunParameters& parameters, RunDirectory& directory);
} // namespace vulnus::app
