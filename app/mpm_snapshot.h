// Converts the MPM points into a ParticleSnapshot for the HDF5 + XDMF output.
#pragma once

#include "app/particle_output.h"
#include "mpm/solver.h"

namespace vulnus::app
{
/// Positions, velocity, stress, failure flag, fiber direction (current, F a0 normalized),
/// material id (body index), equivalent plastic strain, id, reference position.
ParticleSnapshot mpm_snapshot(const mpm::Solver& solver);
} // namespace vulnus::app
