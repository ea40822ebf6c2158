// Particle-to-grid scatter: each share of points writes the nodes it alone touches straight
// into the grid fields and its contested nodes into a small buffer (mpm/point_shares.h).
#include "mpm/particle_to_grid.h"

#include "mpm/point_shares.h"
#include "mpm/stencil.h"

#include <omp.h>

#include <array>
#include <cmath>

namespace vulnus::mpm
{
void mark_active_nodes(const Particles& particles, const TransferSettings& settings, Grid& grid)
{
  grid.clear_active_nodes();
  // Marks the n^3 nodes of each point's stencil from its first node; no weights needed.
  // Sorted points come cell by cell, so a point whose first node repeats the previous one's
  // marks nothing new.
  const int n = nodes_per_axis(settings.shape);
  const int n_shares = omp_get_max_threads();
#pragma omp parallel
  {
    const int team = omp_get_num_threads();
    for (int share = omp_get_thread_num(); share < n_shares; share += team)
      for (std::size_t b = 0; b < particles.n_bodies(); ++b)
      {
        const double lp =
            settings.shape == ShapeFunction::linear ? 0.0 : settings.half_size_cells[b];
        const ShareRange range =
            share_of(particles.begin_of(b), particles.end_of(b), share, n_shares);
        std::array<int, 3> previous{{-1, -1, -1}};
        for (long p = range.begin; p < range.end; ++p)
        {
          const Vector3 s = grid.to_cell_units(particles.position[p]);
          const std::array<int, 3> first{{static_cast<int>(std::floor(s[0] - lp)),
                                          static_cast<int>(std::floor(s[1] - lp)),
                                          static_cast<int>(std::floor(s[2] - lp))}};
          if (first == previous && p > range.begin)
            continue;
          previous = first;
          for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
              for (int i = 0; i < n; ++i)
                grid.mark(grid.node_key(first[0] + i, first[1] + j, first[2] + k), share);
        }
      }
  }
  grid.number_active_nodes(n_shares);
}

namespace
{
template <ShapeFunction shape, bool with_force, bool with_normals>
void scatter(const Particles& particles, const Grid& grid, const TransferSettings& settings,
             const std::size_t b, const ShareRange range, NodeBodyData* fields,
             NodeBodyData* contested)
{
  const std::size_t n_bodies = particles.n_bodies();
  const double lp = settings.half_size_cells[b];
  for (long p = range.begin; p < range.end; ++p)
  {
    const double m = particles.mass[p];
    const Vector3 mv = m * particles.velocity[p];
    Tensor2 volume_stress;
    if constexpr (with_force)
      volume_stress =
          (particles.reference_volume[p] * particles.deformation_gradient[p].determinant()) *
          full_tensor(particles.stress[p]);
    for_each_node<shape>(grid, lp, particles.position[p],
                         [&](const std::int64_t key, const double w, const Vector3& grad_w)
                         {
                           NodeBodyData& node =
                               scatter_target(grid, grid.slot(key), n_bodies, b, fields, contested);
                           node.mass += w * m;
                           node.momentum += w * mv;
                           if constexpr (with_force)
                             node.force -= volume_stress * grad_w;
                           if constexpr (with_normals)
                             node.mass_gradient += m * grad_w;
                         });
  }
}
} // namespace

namespace
{
template <ShapeFunction shape>
void scatter_all_bodies(const Particles& particles, const Grid& grid,
                        const TransferSettings& settings, ScatterBuffers& buffers,
                        GridFields& fields)
{
  const std::size_t n_bodies = particles.n_bodies();
  const long n_entries = static_cast<long>(grid.n_active() * n_bodies);
  const int n_shares = grid.n_point_shares();
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (long e = 0; e < n_entries; ++e)
      fields.data[e] = NodeBodyData();
    const int team = omp_get_num_threads();
    for (int share = omp_get_thread_num(); share < n_shares; share += team)
    {
      clear_contested(buffers.per_share[share], NodeBodyData());
      NodeBodyData* contested = buffers.per_share[share].data();
      for (std::size_t b = 0; b < n_bodies; ++b)
      {
        const ShareRange range =
          share_of(particles.begin_of(b), particles.end_of(b), share, n_shares);
        if (settings.contact_normals)
          scatter<shape, true, true>(particles, grid, settings, b, range, fields.data.data(),
                                     contested);
        else
          scatter<shape, true, false>(particles, grid, settings, b, range, fields.data.data(),
                                      contested);
      }
    }
#pragma omp barrier
    add_contested(grid, n_bodies, buffers.per_share, fields.data.data());
  }
}
} // namespace

void particles_to_grid(const Particles& particles, const Grid& grid,
                       const TransferSettings& settings, ScatterBuffers& buffers,
                       GridFields& fields)
{
  fields.n_bodies = particles.n_bodies();
  fields.resize(grid.n_active());
  size_contested(grid, fields.n_bodies, buffers.per_share);
  if (settings.shape == ShapeFunction::linear)
    scatter_all_bodies<ShapeFunction::linear>(particles, grid, settings, buffers, fields);
  else
    scatter_all_bodies<ShapeFunction::gimp>(particles, grid, settings, buffers, fields);
}
} // namespace vulnus::mpm
