// Particle-to-grid stage: marks the active nodes, then scatters mass, momentum, internal
// force (-V sigma grad w) and, for contact, mass gradients into per-body node fields.
// Threads scatter into private buffers that are summed afterwards, so the result depends on
// the thread count only through the order of floating-point additions.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/particles.h"
#include "mpm/transfer_settings.h"

#include <vector>

namespace vulnus::mpm
{
/// Clears the previous active set and marks every node any point touches; numbers them.
void mark_active_nodes(const Particles& particles, const TransferSettings& settings, Grid& grid);

/// Per-thread scratch space reused across steps.
struct ScatterBuffers
{
  std::vector<std::vector<NodeBodyData>> per_thread;
};

/// Fills fields.data (mass, momentum, force, mass gradient). With_force false skips the
/// stress divergence (used by MUSL's velocity re-projection).
void particles_to_grid(const Particles& particles, const Grid& grid,
                       const TransferSettings& settings, bool with_force,
                       ScatterBuffers& buffers, GridFields& fields);
} // namespace vulnus::mpm
