// The CSV time history of a hybrid run: the MPM columns of mpm_history, then the FE side,
// the whole scene's energy and momentum, and the interface ledger.
#pragma once

#include "coupling/hybrid_solver.h"

#include <string>
#include <vector>

namespace vulnus::simulator
{
/// Energy of the whole scene (J): the MPM side's accounted energy plus FE kinetic, strain and
/// dissipated energy.
double hybrid_scene_energy(const coupling::HybridSolver& solver, const mpm::SceneDiagnostics& m,
                           const vulnus::fem::FeDiagnostics& f);

std::vector<std::string> hybrid_history_columns();
/// One row matching hybrid_history_columns(); initial_energy is the scene energy at t = 0.
std::vector<double> hybrid_history_row(const coupling::HybridSolver& solver,
                                       double initial_energy);
} // namespace vulnus::simulator
