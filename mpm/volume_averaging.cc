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
  return cell_key_at(grid, grid.to_cell_units(x));
}

std::int64_t VolumeAveraging::cell_key_at(const Grid& grid, const Vector3& u)
{
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

/// Adds old_term(p) and new_term(p) of points [begin, end) to their cells' volume_old and
/// volume_new. Serial: two additions per point; the threads fill the per-point terms before.
template <class OldTerm, class NewTerm>
void add_to_cells(const long begin, const long end, VolumeAveraging& s, OldTerm&& old_term,
                  NewTerm&& new_term)
{
  for (long p = begin; p < end; ++p)
  {
    const std::int64_t key = s.cell[p];
    if (key < 0)
      continue;
    if (s.volume_old[key] == 0.0)
      s.touched.push_back(key);
    s.volume_old[key] += old_term(p);
    s.volume_new[key] += new_term(p);
  }
}

void sum_cell_volumes(const long begin, const long end, const Particles& particles,
                      VolumeAveraging& s)
{
  clear_cell_sums(s);
  s.point_volume.resize(particles.size());
#pragma omp parallel for schedule(static)
  for (long p = begin; p < end; ++p)
    if (s.cell[p] >= 0)
      s.point_volume[p] =
        particles.reference_volume[p] * particles.deformation_gradient[p].determinant();
  add_to_cells(
      begin, end, s, [&](const long p) { return particles.reference_volume[p] * s.j_old[p]; },
      [&](const long p) { return s.point_volume[p]; });
}

/// Per cell of the points' present positions (debris left out): their summed volume into
/// volume_old and, with `pressure`, its integral of the mean stress into volume_new; each
/// point's cell into cell and its volume into point_volume.
void sum_cells_where_points_are(const Grid& grid, const long begin, const long end,
                                const Particles& particles, VolumeAveraging& s,
                                const bool pressure)
{
  s.prepare(grid, particles.size());
  clear_cell_sums(s);
  s.point_volume.resize(particles.size());
#pragma omp parallel for schedule(static)
  for (long p = begin; p < end; ++p)
  {
    s.cell[p] = particles.failure[p] == materials::total_failure
                  ? -1
                  : VolumeAveraging::cell_key(grid, particles.position[p]);
    s.point_volume[p] =
      particles.reference_volume[p] * particles.deformation_gradient[p].determinant();
  }
  add_to_cells(
      begin, end, s, [&](const long p) { return s.point_volume[p]; },
      [&](const long p)
      { return pressure ? s.point_volume[p] * particles.stress[p].head<3>().sum() / 3.0 : 0.0; });
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
  const std::array<std::int64_t, 8> keys = cell_corner_keys(grid, key);
  for (int corner = 0; corner < 8; ++corner)
  {
    const std::int32_t slot = grid.slot(keys[corner]);
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

void VolumeAveraging::clear_pair(const std::size_t n_points)
{
  paired_stress.resize(n_points);
  std::fill(paired_stress.begin(), paired_stress.end(), 0.0);
}

void prepare_grid_flux_pair(const Grid& grid, const long begin, const long end,
                            const Particles& particles, VolumeAveraging& s)
{
  // The cells and volumes the deformation update will sum (the same points, positions and J).
  sum_cells_where_points_are(grid, begin, end, particles, s, false);
  s.paired_stress.resize(particles.size(), 0.0);
#pragma omp parallel
  {
    // Sorted points come cell by cell: each cell's corners are looked up once.
    std::int64_t last_cell = -1;
    bool last_pairs = false;
#pragma omp for schedule(static)
    for (long p = begin; p < end; ++p)
    {
      s.paired_stress[p] = 0.0;
      const std::int64_t key = s.cell[p];
      if (key < 0)
        continue;
      if (key != last_cell)
      {
        last_cell = key;
        const std::array<std::int64_t, 8> corners = cell_corner_keys(grid, key);
        last_pairs = filled(grid, s.volume_old[key]) &&
                     std::none_of(corners.begin(), corners.end(),
                                  [&](const std::int64_t corner) { return grid.slot(corner) < 0; });
      }
      if (last_pairs)
        s.paired_stress[p] = s.point_volume[p] * particles.stress[p].head<3>().sum() / 3.0;
    }
  }
}

long unpair_cells_without_mass(const Grid& grid, const TransferSettings& transfer,
                               const std::size_t body, const long begin, const long end,
                               const Particles& particles, GridFields& fields, VolumeAveraging& s)
{
  std::vector<long> unpaired;
#pragma omp parallel
  {
    std::int64_t last_cell = -1;
    bool last_has_mass = true;
#pragma omp for schedule(static)
    for (long p = begin; p < end; ++p)
    {
      if (s.paired_stress[p] == 0.0)
        continue;
      if (s.cell[p] != last_cell)
      {
        last_cell = s.cell[p];
        std::array<std::size_t, 8> entries;
        last_has_mass = corner_entries(grid, fields.data, fields.n_bodies, body, last_cell,
                                       entries);
      }
      if (last_has_mass)
        continue;
#pragma omp critical(vulnus_unpair)
      unpaired.push_back(p);
    }
  }
  // The points in order, whatever the team size.
  std::sort(unpaired.begin(), unpaired.end());
  const double lp = transfer.half_size_cells[body];
  // Serial and rare: only where the body's points leave a corner of their cell without mass.
  with_shape(transfer.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
               for (const long p : unpaired)
               {
                 const double paired = s.paired_stress[p];
                 auto force = [&](const std::int64_t node) -> Vector3&
                 {
                   const std::size_t slot = std::size_t(grid.slot(node));
                   return fields.data[slot * fields.n_bodies + body].force;
                 };
                 auto give_back = [&](const std::int64_t node, const double, const Vector3& grad)
                 { force(node) -= paired * grad; };
                 for_each_node<shape>(grid, lp, particles.position[p],
                                      particles.deformation_gradient[p], give_back);
                 const std::array<std::int64_t, 8> corners = cell_corner_keys(grid, s.cell[p]);
                 for (int corner = 0; corner < 8; ++corner)
                   force(corners[corner]) += paired * cell_mean_shape_gradient(grid, corner);
                 s.paired_stress[p] = 0.0;
               }
             });
  return long(unpaired.size());
}
} // namespace vulnus::mpm
