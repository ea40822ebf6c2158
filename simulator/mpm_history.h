// The CSV time history of an MPM run: column names and one row of diagnostics per record.
#pragma once

#include "mpm/solver.h"

#include <string>
#include <vector>

namespace vulnus::simulator
{
std::vector<std::string> mpm_history_columns();

/// One row matching mpm_history_columns().
std::vector<double> mpm_history_row(const mpm::Solver& solver, const mpm::SceneDiagnostics& d);

} // namespace vulnus::simulator
