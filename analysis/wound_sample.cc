// Collects the target's failed points and intact totals over the ranks for the wound metrics,
// the points that left the grid included.
#include "analysis/wound_sample.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace vulnus::analysis
{
namespace
{
constexpr std::size_t record_size = 3 * sizeof(double) + sizeof(double) + 1;

void append_record(std::vector<char>& bytes, const mpm::Vector3& x, const double volume,
                   const std::uint8_t flag)
{
  const std::size_t offset = bytes.size();
  bytes.resize(offset + record_size);
  std::memcpy(bytes.data() + offset, x.data(), 3 * sizeof(double));
  std::memcpy(bytes.data() + offset + 3 * sizeof(double), &volume, sizeof(double));
  bytes[offset + 4 * sizeof(double)] = static_cast<char>(flag);
}
} // namespace

WoundSample collect_wound_sample(const mpm::Solver& solver)
{
  const mpm::Particles& p = solver.points();
  const mpm::Vector3 axis = solver.flight_direction();
  const int projectile = solver.projectile();
  WoundSample sample;
  double entrance = std::numeric_limits<double>::max(), exit = -entrance;
  std::vector<char> failed;
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
  {
    // The target: every deformable body other than the projectile.
    if (static_cast<int>(b) == projectile || solver.body_material(b).is_rigid())
      continue;
    sample.has_target = true;
    const double half_spacing =
      0.5 * solver.scene().cell_size / solver.scene().bodies[b].particles_per_cell;
    for (std::size_t i = p.begin_of(b); i < p.end_of(b); ++i)
    {
      const mpm::Vector3 X = p.reference_position[i].cast<double>();
      const double along = X.dot(axis);
      entrance = std::min(entrance, along - half_spacing);
      exit = std::max(exit, along + half_spacing);
      const std::uint8_t flag = p.failure[i];
      if (flag == 0)
      {
        ++sample.n_intact;
        sample.intact_volume += p.reference_volume[i];
      }
      else
        append_record(failed, X, p.reference_volume[i], flag);
    }
  }
  // Target points that left the grid keep their place in the wound.
  for (const mpm::DepartedPoint& d : solver.departed_points())
  {
    if (static_cast<int>(d.body) == projectile || solver.body_material(d.body).is_rigid())
      continue;
    const double half_spacing =
      0.5 * solver.scene().cell_size / solver.scene().bodies[d.body].particles_per_cell;
    const double along = d.reference_position.dot(axis);
    entrance = std::min(entrance, along - half_spacing);
    exit = std::max(exit, along + half_spacing);
    if (d.failure == 0)
    {
      ++sample.n_intact;
      sample.intact_volume += d.reference_volume;
    }
    else
      append_record(failed, d.reference_position, d.reference_volume, d.failure);
  }
  const mpm::RankGroup& ranks = solver.rank_group();
  sample.entrance = ranks.min(entrance);
  sample.exit = ranks.max(exit);
  sample.n_intact = ranks.sum(sample.n_intact);
  ranks.sum(&sample.intact_volume, 1);
  sample.n_points = ranks.sum(static_cast<std::uint64_t>(p.size()));

  std::vector<std::vector<char>> parts;
  if (ranks.distributed())
    parts = ranks.gather_to_root(failed);
  else
    parts.push_back(std::move(failed));
  for (const std::vector<char>& part : parts)
    for (std::size_t offset = 0; offset + record_size <= part.size(); offset += record_size)
    {
      mpm::Vector3 x;
      double volume = 0.0;
      std::memcpy(x.data(), part.data() + offset, 3 * sizeof(double));
      std::memcpy(&volume, part.data() + offset + 3 * sizeof(double), sizeof(double));
      sample.failed_position.push_back(x);
      sample.failed_volume.push_back(volume);
      sample.failed_flag.push_back(static_cast<std::uint8_t>(part[offset + 4 * sizeof(double)]));
    }
  return sample;
}

WoundMetrics wound_metrics_of(const WoundSample& sample, const mpm::Solver& solver)
{
  if (!sample.has_target)
    return WoundMetrics();
  // Intact points enter the metrics only through the intact count and volume.
  WoundMetrics m = compute_wound_metrics(
    sample.failed_position, sample.failed_volume, sample.failed_flag, solver.flight_direction(),
    sample.entrance, sample.exit, solver.scene().cell_size);
  m.counts[0] += sample.n_intact;
  m.volumes[0] += sample.intact_volume;
  return m;
}
} // namespace vulnus::analysis
