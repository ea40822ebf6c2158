// Cell-averaged volume change of the points (F-bar for MPM).
#include "mpm/volume_averaging.h"

#include "materials/material.h"

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
} // namespace

void average_volume_changes(const long begin, const long end, Particles& particles,
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
void average_cell_pressures(const Grid& grid, const long begin, const long end,
                            Particles& particles, VolumeAveraging& s)
{
  s.prepare(grid, particles.size());
  clear_cell_sums(s);
  // volume_old: the cell's volume, volume_new: its integral of the pressure.
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
    s.volume_new[key] += volume * particles.stress[p].head<3>().sum() / 3.0;
  }
#pragma omp parallel for schedule(static)
  for (long p = begin; p < end; ++p)
  {
    const std::int64_t key = s.cell[p];
    if (key < 0 || !(s.volume_old[key] > 0.0))
      continue;
    const double change = s.volume_new[key] / s.volume_old[key] - particles.stress[p].head<3>().sum() / 3.0;
    particles.stress[p].head<3>().array() += change;
  }
}
} // namespace vulnus::mpm
