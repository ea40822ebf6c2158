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
/// share of points (one per thread) touches it; numbers them. With `point_cells`, also the
/// corners of the cell holding each point (the grid flux's pair writes there; only CPDI's
/// stencil can miss them).
void mark_active_nodes(const Particles& particles, const TransferSettings& settings, Grid& grid,
                       bool point_cells = false);

/// Grid flux's force pair (mpm/volume_averaging.h), per point: the volume times the mean
/// stress the scatter takes on the point's cell's mean corner gradients instead of its own
/// shape gradients (0: none), and the key of that cell.
struct GridFluxPair
{
  const double* volume_mean_stress;
  const std::int64_t* cell;
};

/// Fills fields.data (mass, momentum, force, mass gradient) on the nodes mark_active_nodes
/// numbered. point_force, if given, holds an external force on each point (indexed like the
/// points), spread with the point's weights; `pair`, if given, grid flux's force pair.
void particles_to_grid(const Particles& particles, const Grid& grid,
                       const TransferSettings& settings, ScatterBuffers& buffers,
                       GridFields& fields, const Vector3* point_force = nullptr,
                       const GridFluxPair* pair = nullptr);

/// Fills fields.stress_sum (sum_p N_i(x_p) sigma_p per node and body) on the active nodes,
/// for the contact's compression criterion.
void scatter_nodal_stress(const Particles& particles, const Grid& grid,
                          const TransferSettings& settings, ScatterBuffers& buffers,
                          GridFields& fields);
} // namespace vulnus::mpm
