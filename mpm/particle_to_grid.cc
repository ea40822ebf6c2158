// Particle-to-grid scatter: each share of points writes the nodes it alone touches straight
// into the grid fields and its contested nodes into a small buffer (mpm/point_shares.h).
#include "mpm/particle_to_grid.h"

#include "mpm/point_shares.h"
#include "mpm/stencil.h"

#include <omp.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace vulnus::mpm
{
void mark_active_nodes(const Particles& particles, const TransferSettings& settings, Grid& grid,
                       const bool point_cells)
{
  grid.clear_active_nodes();
  // Marks the blocks of each point's stencil (for_each_stencil_block); no weights needed.
  // Sorted points come cell by cell, so a block that repeats the one marked before it (the
  // previous point's, or the previous CPDI corner's) marks nothing new.
  const int n_shares = omp_get_max_threads();
  visit_shares_in_parallel(
      particles, n_shares,
      [&](const int share, const std::size_t b, const ShareRange range)
      {
        const double lp =
            settings.shape == ShapeFunction::linear ? 0.0 : settings.half_size_cells[b];
        std::array<int, 3> previous{{0, 0, 0}};
        bool marked_any = false;
        auto mark_block = [&](const std::array<int, 3>& first, const int width, const int depth)
        {
          if (marked_any && first == previous)
            return;
          marked_any = true;
          previous = first;
          for (int k = 0; k < depth; ++k)
            for (int j = 0; j < width; ++j)
              for (int i = 0; i < width; ++i)
                grid.mark(grid.node_key(first[0] + i, first[1] + j, first[2] + k), share);
        };
        const bool mark_cells = point_cells && settings.shape == ShapeFunction::cpdi;
        for (long p = range.begin; p < range.end; ++p)
        {
          for_each_stencil_block(grid, settings.shape, lp, particles.position[p],
                                 particles.deformation_gradient[p], mark_block);
          if (mark_cells) // the cell's corners are the linear stencil
            for_each_stencil_block(grid, ShapeFunction::linear, 0.0, particles.position[p],
                                   particles.deformation_gradient[p], mark_block);
        }
      });
  grid.number_active_nodes(n_shares);
  grid.set_point_cells_marked(point_cells || settings.shape != ShapeFunction::cpdi);
}

namespace
{
template <ShapeFunction shape, bool with_normals, bool affine>
void scatter(const Particles& particles, const Grid& grid, const TransferSettings& settings,
             const std::size_t b, const ShareRange range, NodeBodyData* fields,
             NodeBodyData* contested, const Vector3* point_force, const GridFluxPair* pair)
{
  const std::size_t n_bodies = particles.n_bodies();
  const double lp = settings.half_size_cells[b];
  // Sorted points come cell by cell: the pair's corner slots are looked up once per cell.
  std::int64_t pair_cell = -1;
  std::array<std::int32_t, 8> pair_slots{};
  for (long p = range.begin; p < range.end; ++p)
  {
    const double m = particles.mass[p];
    const Vector3 mv = m * particles.velocity[p];
    const Tensor2 mC = affine ? Tensor2(m * particles.affine_velocity[p].cast<double>())
                              : Tensor2::Zero();
    Tensor2 volume_stress =
        (particles.reference_volume[p] * particles.deformation_gradient[p].determinant()) *
        full_tensor(particles.stress[p]);
    const double paired = pair ? pair->volume_mean_stress[p] : 0.0;
    if (paired != 0.0)
      volume_stress.diagonal().array() -= paired;
    // The hoop stress's pull towards the axis (mpm/axisymmetry.h).
    const double hoop =
      grid.axisymmetric() ? volume_stress(2, 2) / particles.position[p][0] : 0.0;
    auto add = [&](const std::int64_t key, const double w, const Vector3& grad_w,
                   const Vector3& momentum)
    {
      NodeBodyData& node = scatter_target(grid, grid.slot(key), n_bodies, b, fields, contested);
      const double wm = w * m;
      node.mass += wm;
      node.momentum += w * momentum;
      if (point_force)
        node.force += w * point_force[p] - volume_stress * grad_w;
      else
        node.force -= volume_stress * grad_w;
      node.force[0] -= hoop * w;
      if constexpr (with_normals)
      {
        node.mass_gradient += m * grad_w;
        node.mass_position += wm * particles.position[p];
      }
    };
    // The node offset is computed only for APIC's affine momentum.
    if constexpr (affine)
      for_each_node<shape>(grid, lp, particles.position[p], particles.deformation_gradient[p],
                           [&](const std::int64_t key, const double w, const Vector3& grad_w,
                               const Vector3& offset)
                           { add(key, w, grad_w, (mv + mC * offset).eval()); });
    else
      for_each_node<shape>(grid, lp, particles.position[p], particles.deformation_gradient[p],
                           [&](const std::int64_t key, const double w, const Vector3& grad_w)
                           { add(key, w, grad_w, mv); });
    if (paired != 0.0)
    {
      if (pair->cell[p] != pair_cell)
      {
        pair_cell = pair->cell[p];
        const std::array<std::int64_t, 8> corners = cell_corner_keys(grid, pair_cell);
        for (int corner = 0; corner < 8; ++corner)
          pair_slots[corner] = grid.slot(corners[corner]);
      }
      for (int corner = 0; corner < 8; ++corner)
        scatter_target(grid, pair_slots[corner], n_bodies, b, fields, contested).force -=
            paired * cell_mean_shape_gradient(grid, corner);
    }
  }
}
} // namespace

void particles_to_grid(const Particles& particles, const Grid& grid,
                       const TransferSettings& settings, ScatterBuffers& buffers,
                       GridFields& fields, const Vector3* point_force,
                       const GridFluxPair* pair)
{
  // A pair's corner outside the point's marked stencil could belong to another share.
  if (pair && !grid.point_cells_marked())
    throw std::logic_error("particles_to_grid: grid flux's force pair needs the nodes marked "
                           "with the points' cells (mark_active_nodes with point_cells)");
  fields.n_bodies = particles.n_bodies();
  fields.resize(grid.n_active());
  with_shape(settings.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
               scatter_by_shares(grid, particles, NodeBodyData(), fields.data, buffers.per_share,
                                 [&](int, const std::size_t b, const ShareRange range,
                                     NodeBodyData* direct, NodeBodyData* contested)
                                 {
                                   const bool n = settings.contact_normals, a = settings.affine;
                                   if (n && a)
                                     scatter<shape, true, true>(particles, grid, settings, b,
                                                                range, direct, contested,
                                                                point_force, pair);
                                   else if (n)
                                     scatter<shape, true, false>(particles, grid, settings, b,
                                                                 range, direct, contested,
                                                                point_force, pair);
                                   else if (a)
                                     scatter<shape, false, true>(particles, grid, settings, b,
                                                                 range, direct, contested,
                                                                point_force, pair);
                                   else
                                     scatter<shape, false, false>(particles, grid, settings, b,
                                                                  range, direct, contested,
                                                                point_force, pair);
                                 });
             });
}

void scatter_nodal_stress(const Particles& particles, const Grid& grid,
                          const TransferSettings& settings, ScatterBuffers& buffers,
                          GridFields& fields)
{
  const std::size_t n_bodies = particles.n_bodies();
  fields.stress_sum.resize(grid.n_active() * n_bodies);
  with_shape(settings.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
               scatter_by_shares(
                 grid, particles, SymmetricTensor(SymmetricTensor::Zero()), fields.stress_sum,
                 buffers.stress_per_share,
                 [&](int, const std::size_t b, const ShareRange range,
                     SymmetricTensor* direct, SymmetricTensor* contested)
                 {
                   const double lp = settings.half_size_cells[b];
                   for (long p = range.begin; p < range.end; ++p)
                     for_each_node<shape>(grid, lp, particles.position[p],
                                          particles.deformation_gradient[p],
                                          [&](const std::int64_t key, const double w, const Vector3&)
                                          {
                                            scatter_target(grid, grid.slot(key), n_bodies, b,
                                                           direct, contested) +=
                                              w * particles.stress[p];
                                          });
                 });
             });
}
} // namespace vulnus::mpm
