// Particle-to-grid scatter with thread-private buffers.
#include "mpm/particle_to_grid.h"

#include "mpm/stencil.h"

#include <omp.h>

#include <cmath>

namespace vulnus::mpm
{
void mark_active_nodes(const Particles& particles, const TransferSettings& settings, Grid& grid)
{
  grid.clear_active_nodes();
  // Marks the n^3 nodes of each point's stencil from its first node; no weights needed.
  const int n = nodes_per_axis(settings.shape);
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    const double lp = settings.shape == ShapeFunction::linear ? 0.0 : settings.half_size_cells[b];
    const long begin = particles.begin_of(b), end = particles.end_of(b);
#pragma omp parallel for schedule(static)
    for (long p = begin; p < end; ++p)
    {
      const Vector3 s = grid.to_cell_units(particles.position[p]);
      const int i0 = static_cast<int>(std::floor(s[0] - lp));
      const int j0 = static_cast<int>(std::floor(s[1] - lp));
      const int k0 = static_cast<int>(std::floor(s[2] - lp));
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            grid.mark(grid.node_key(i0 + i, j0 + j, k0 + k));
    }
  }
  grid.number_active_nodes();
}

namespace
{
template <ShapeFunction shape, bool with_force, bool with_normals>
void scatter(const Particles& particles, const Grid& grid, const TransferSettings& settings,
             const std::size_t n_bodies, std::vector<NodeBodyData>& out, const std::size_t b,
             const long begin, const long end)
{
  const double lp = settings.half_size_cells[b];
#pragma omp for schedule(static) nowait
  for (long p = begin; p < end; ++p)
  {
    const double m = particles.mass[p];
    const Vector3 mv = m * particles.velocity[p];
    Tensor2 volume_stress;
    if constexpr (with_force)
      volume_stress = (particles.reference_volume[p] * particles.deformation_gradient[p].determinant()) *
                      full_tensor(particles.stress[p]);
    for_each_node<shape>(grid, lp, particles.position[p],
                         [&](const std::int64_t key, const double w, const Vector3& grad_w) {
                           NodeBodyData& node = out[grid.slot(key) * n_bodies + b];
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

void particles_to_grid(const Particles& particles, const Grid& grid,
                       const TransferSettings& settings, const bool with_force,
                       ScatterBuffers& buffers, GridFields& fields)
{
  const std::size_t n_bodies = particles.n_bodies();
  fields.n_bodies = n_bodies;
  const std::size_t n_entries = grid.n_active() * n_bodies;
  fields.resize(grid.n_active());
  const int n_threads = omp_get_max_threads();
  buffers.per_thread.resize(n_threads);

  with_shape(settings.shape, [&](auto shape_constant) {
    constexpr ShapeFunction shape = decltype(shape_constant)::value;
#pragma omp parallel num_threads(n_threads)
    {
      const int t = omp_get_thread_num();
      std::vector<NodeBodyData>& out = t == 0 ? fields.data : buffers.per_thread[t];
      if (t != 0)
        out.resize(n_entries);
#pragma omp barrier
      // Every thread clears an equal share of every buffer (fields.data included).
#pragma omp for schedule(static)
      for (long e = 0; e < static_cast<long>(n_entries); ++e)
      {
        fields.data[e] = NodeBodyData();
        for (int other = 1; other < n_threads; ++other)
          buffers.per_thread[other][e] = NodeBodyData();
      }
      for (std::size_t b = 0; b < n_bodies; ++b)
      {
        const long begin = particles.begin_of(b), end = particles.end_of(b);
        if (with_force && settings.contact_normals)
          scatter<shape, true, true>(particles, grid, settings, n_bodies, out, b, begin, end);
        else if (with_force)
          scatter<shape, true, false>(particles, grid, settings, n_bodies, out, b, begin, end);
        else
          scatter<shape, false, false>(particles, grid, settings, n_bodies, out, b, begin, end);
      }
#pragma omp barrier
#pragma omp for schedule(static)
      for (long e = 0; e < static_cast<long>(n_entries); ++e)
        for (int other = 1; other < n_threads; ++other)
          fields.data[e].add(buffers.per_thread[other][e]);
    }
  });
}
} // namespace vulnus::mpm
