// Converts the MPM points into a ParticleSnapshot for the HDF5 + XDMF output.
#pragma once

#include "io/particle_output.h"
#include "mpm/solver.h"

namespace vulnus::simulator
{
/// Positions, velocity, stress, failure flag, fiber direction (current, F a0 normalized),
/// material id (body index), equivalent plastic strain, id, reference position (stress as
/// Tensor6). Position, velocity, stress and reference position are borrowed from the solver,
/// not copied: write the snapshot before the solver steps again.
io::ParticleSnapshot mpm_snapshot(const mpm::Solver& solver);
} // namespace vulnus::simulator
