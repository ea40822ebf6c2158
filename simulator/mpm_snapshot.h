// Converts the MPM points into a Snapshot for the HDF5 + XDMF output.
#pragma once

#include "io/xdmf_series.h"
#include "mpm/solver.h"

namespace vulnus::simulator
{
/// Positions, velocity, stress, failure flag, fiber direction (current, F a0 normalized),
/// material id (body index), equivalent plastic strain, id, reference position, displacement
/// and MPI rank (stress as Tensor6; the FE mesh output shares the names). Position, velocity, stress and reference position are borrowed from the solver,
/// not copied: write the snapshot before the solver steps again.
io::Snapshot mpm_snapshot(const mpm::Solver& solver);
} // namespace vulnus::simulator
