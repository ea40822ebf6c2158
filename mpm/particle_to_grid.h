// Particle-to-grid stage: marks the active nodes, then scatters mass, momentum, internal
// force (-V sigma grad w) and, for contact, mass gradients into per-body node fields.
// Each share of points writes its own nodes directly and its contested ones into a buffer that
// is summed afterwards (mpm/point_shares.h), so the result depends on the thread count only
// through the order of floating-point additions at the seams.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/particles.h"
#include "mpm/point_shares.h"
#include "mpm/transfer_settings.h"

namespace vulnus::mpm
{
/// Clears the previous active set and marks every node any point touches, recording which
/// share of points (one per thread) touches it; numbers them.
void mark_active_nodes(const Particles& particles, const TransferSettings& settings, Grid& grid);

/// Fills fields.data (mass, momentum, force, mass gradient) on the nodes mark_active_nodes
/// numbered. point_force, if given, holds an external force on each point (indexed like the
/// points), spread with the point's weights.
void particles_to_grid(const Particles& particles, const Grid& grid,
                       const TransferSettings& settings, ScatterBuffers& buffers,
                       GridFields& fields, const Vector3* point_force = nullptr);

/// Fills fields.stress_sum (sum_p N_i(x_p) sigma_p per node and body) on the active nodes,
/// for the contact's compression criterion.
void scatter_nodal_stress(const Particles& particles, const Grid& grid,
                          const TransferSettings& settings, ScatterBuffers& buffers,
                          GridFields& fields);
} // namespace vulnus::mpm
