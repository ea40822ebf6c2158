// Cell-averaged volume change of the points (F-bar for MPM).
#include "mpm/volume_averaging.h"

#include "materials/material.h"
#include "mpm/stencil.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vulnus::mpm
{
void VolumeAveraging::prepare(const Grid& grid, const std::size_t n_points)
{
  j_old.resize(n_points);
  cell.resize(n_points);
  if (volume_old.size() != grid.n_box_nodes())
  {
    volume_old.assign(grid.n_box_nodes(), 0.0);
    volume_new.assign(grid.n_box_nodes(), 0.0);
    touched.clear();
  }
}

std::int64_t VolumeAveraging::cell_key(const Grid& grid, const Vector3& x)
{
  const Vector3 u = grid.to_cell_units(x);
  const int i = static_cast<int>(std::floor(u[0]));
  const int j = static_cast<int>(std::floor(u[1]));
  const int k = static_cast<int>(std::floor(u[2]));
  if (!std::isfinite(u.sum()) || !grid.has_node(i, j, k) || !grid.has_node(i + 1, j + 1, k + 1))
    return -1;
  return grid.node_key(i, j, k);
}

namespace
{
void clear_cell_sums(VolumeAveraging& s)
{
  for (const std::int64_t key : s.touched)
    s.volume_old[key] = s.volume_new[key] = 0.0;
  s.touched.clear();
}

void sum_cell_volumes(const long begin, const long end, const Particles& particles,
                      VolumeAveraging& s)
{
  clear_cell_sums(s);
  // Serial: two additions per point, cheaper than the threads' bookkeeping.
  for (long p = begin; p < end; ++p)
  {
    const std::int64_t key = s.cell[p];
    if (key < 0)
      continue;
    if (s.volume_old[key] == 0.0)
      s.touched.push_back(key);
    const double v0 = particles.reference_volume[p];
    s.volume_old[key] += v0 * s.j_old[p];
    s.volume_new[key] += v0 * particles.deformation_gradient[p].determinant();
  }
}

/// Per cell of the points' present positions (debris left out): their summed volume into
/// volume_old and, with `pressure`, its integral of the mean stress into volume_new.
void sum_cells_where_points_are(const Grid& grid, const long begin, const long end,
                                const Particles& particles, VolumeAveraging& s,
                                const bool pressure)
{
  s.prepare(grid, particles.size());
  clear_cell_sums(s);
  for (long p = begin; p < end; ++p)
  {
    const std::int64_t key = particles.failure[p] == materials::total_failure
                               ? -1
                               : VolumeAveraging::cell_key(grid, particles.position[p]);
    s.cell[p] = key;
    if (key < 0)
      continue;
    if (s.volume_old[key] == 0.0)
      s.touched.push_back(key);
    const double volume =
      particles.reference_volume[p] * particles.deformation_gradient[p].determinant();
    s.volume_old[key] += volume;
    if (pressure)
      s.volume_new[key] += volume * particles.stress[p].head<3>().sum() / 3.0;
  }
}

void scale_to_cell_ratios(const long begin, const long end, Particles& particles,
                          const VolumeAveraging& s)
{
#pragma omp parallel for schedule(static)
  for (long p = begin; p < end; ++p)
  {
    const std::int64_t key = s.cell[p];
    if (key < 0)
      continue;
    Tensor2& F = particles.deformation_gradient[p];
    const double cell_ratio = s.volume_new[key] / s.volume_old[key];
    const double own_ratio = F.determinant() / s.j_old[p];
    // An inverted point keeps its F: the material update names it.
    if (cell_ratio > 0.0 && own_ratio > 0.0)
      F *= std::cbrt(cell_ratio / own_ratio);
  }
}

/// Gradient of node `corner` (bits: +x, +y, +z) of a cell, averaged over the cell.
Vector3 cell_mean_shape_gradient(const Grid& grid, const int corner)
{
  const int a = corner & 1, b = (corner >> 1) & 1, c = (corner >> 2) & 1;
  return 0.25 * grid.inverse_cell_size() * Vector3(2.0 * a - 1.0, 2.0 * b - 1.0, 2.0 * c - 1.0);
}

/// Whether a cell's points, of summed volume `volume`, fill enough of it for the grid flux.
bool filled(const Grid& grid, const double volume)
{
  return volume >= VolumeAveraging::grid_flux_min_fill * std::pow(grid.cell_size(), 3);
}

/// The entries (slot * n_bodies + body) of the cell's 8 corners, in cell_mean_shape_gradient's
/// order; false where a corner is inactive or holds no mass of the body. The one rule for
/// which cells the grid flux and its force pair apply to.
bool corner_entries(const Grid& grid, const std::vector<NodeBodyData>& node_data,
                    const std::size_t n_bodies, const std::size_t body, const std::int64_t key,
                    std::array<std::size_t, 8>& entries)
{
  const auto ijk = grid.node_ijk(key);
  for (int corner = 0; corner < 8; ++corner)
  {
    const std::int32_t slot = grid.slot(grid.node_key(
        ijk[0] + (corner & 1), ijk[1] + ((corner >> 1) & 1), ijk[2] + ((corner >> 2) & 1)));
    if (slot < 0)
      return false;
    entries[corner] = std::size_t(slot) * n_bodies + body;
    if (!(node_data[entries[corner]].mass > 0.0))
      return false;
  }
  return true;
}

/// The cell's mean velocity gradient (its faces' flux), or false where corner_entries is.
bool cell_mean_gradient(const Grid& grid, const NodalVelocities& nodal, const std::int64_t key,
                        Tensor2& L)
{
  std::array<std::size_t, 8> entries;
  if (!corner_entries(grid, nodal.node_data, nodal.n_bodies, nodal.body, key, entries))
    return false;
  L.setZero();
  for (int corner = 0; corner < 8; ++corner)
    L.noalias() +=
        nodal.velocity[entries[corner]] * cell_mean_shape_gradient(grid, corner).transpose();
  return true;
}
} // namespace

void average_volume_changes(const long begin, const long end, Particles& particles,
                            VolumeAveraging& s)
{
  sum_cell_volumes(begin, end, particles, s);
  scale_to_cell_ratios(begin, end, particles, s);
}

void impose_grid_flux_volume_changes(const Grid& grid, const NodalVelocities& nodal,
                                     const long begin, const long end, Particles& particles,
                                     VolumeAveraging& s)
{
  sum_cell_volumes(begin, end, particles, s);
  const double dt = nodal.time_step;
  const long n_cells = long(s.touched.size());
#pragma omp parallel for schedule(static)
  for (long c = 0; c < n_cells; ++c)
  {
    const std::int64_t key = s.touched[c];
    Tensor2 L;
    if (!filled(grid, s.volume_old[key]) || !cell_mean_gradient(grid, nodal, key, L))
      continue;
    const Tensor2 I = Tensor2::Identity();
    const double ratio = nodal.midpoint
                           ? (I + (0.5 * dt) * L).determinant() / (I - (0.5 * dt) * L).determinant()
                           : (I + dt * L).determinant();
    s.volume_new[key] = ratio * s.volume_old[key];
  }
  scale_to_cell_ratios(begin, end, particles, s);
}

void average_cell_pressures(const Grid& grid, const long begin, const long end,
                            Particles& particles, VolumeAveraging& s)
{
  // volume_old: the cell's volume, volume_new: its integral of the pressure.
  sum_cells_where_points_are(grid, begin, end, particles, s, true);
#pragma omp parallel for schedule(static)
  for (long p = begin; p < end; ++p)
  {
    const std::int64_t key = s.cell[p];
    if (key < 0 || !(s.volume_old[key] > 0.0))
      continue;
    const double change =
        s.volume_new[key] / s.volume_old[key] - particles.stress[p].head<3>().sum() / 3.0;
    particles.stress[p].head<3>().array() += change;
  }
}

void pair_forces_with_grid_flux(const Grid& grid, const TransferSettings& transfer,
                                const std::size_t body, const long begin, const long end,
                                const Particles& particles, GridFields& fields,
                                VolumeAveraging& s)
{
  // The cells and volumes the deformation update will sum (the same points, positions and J).
  sum_cells_where_points_are(grid, begin, end, particles, s, false);
  const double lp = transfer.half_size_cells[body];
  // Serial: neighbouring cells share nodes.
  with_shape(transfer.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
               for (long p = begin; p < end; ++p)
               {
                 const std::int64_t key = s.cell[p];
                 if (key < 0 || !filled(grid, s.volume_old[key]))
                   continue;
                 std::array<std::size_t, 8> corners;
                 if (!corner_entries(grid, fields.data, fields.n_bodies, body, key, corners))
                   continue;
                 const double volume_mean_stress =
                     particles.reference_volume[p] *
                     particles.deformation_gradient[p].determinant() *
                     particles.stress[p].head<3>().sum() / 3.0;
                 // The scatter added -V sigma_m grad w at each node of the point's stencil.
                 auto remove_own = [&](const std::int64_t node, const double,
                                       const Vector3& grad_w)
                 {
                   fields.data[std::size_t(grid.slot(node)) * fields.n_bodies + body].force +=
                       volume_mean_stress * grad_w;
                 };
                 for_each_node<shape>(grid, lp, particles.position[p],
                                      particles.deformation_gradient[p], remove_own);
                 for (int corner = 0; corner < 8; ++corner)
                   fields.data[corners[corner]].force -=
                       volume_mean_stress * cell_mean_shape_gradient(grid, corner);
               }
             });
}
} // namespace vulnus::mpm
