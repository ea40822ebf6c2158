// Collects the target's failed points and intact totals over the ranks for the wound metrics,
// the points that left the grid included.
#include "analysis/wound_sample.h"

#include <algorithm>
#include <cmath>
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
/// Collective: every rank's records, appended to the sample on rank 0 (the others keep their
/// own).
void append_gathered(WoundSample& sample, const mpm::RankGroup& ranks, std::vector<char> failed)
{
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
}
} // namespace

WoundSample collect_wound_sample(const mpm::Solver& solver)
{
  const mpm::Particles& p = solver.points();
  const int projectile = solver.projectile();
  WoundSample sample;
  constexpr double inf = std::numeric_limits<double>::infinity();
  mpm::Vector3 lower(inf, inf, inf), upper(-inf, -inf, -inf);
  auto extend = [&lower, &upper](const mpm::Vector3& x, const double half_spacing) {
    lower = lower.cwiseMin(x - mpm::Vector3::Constant(half_spacing));
    upper = upper.cwiseMax(x + mpm::Vector3::Constant(half_spacing));
  };
  double projectile_sums[4] = {0, 0, 0, 0}; // reference volume, first moment
  auto add_to_projectile = [&projectile_sums](const mpm::Vector3& x, const double volume) {
    projectile_sums[0] += volume;
    for (int d = 0; d < 3; ++d)
      projectile_sums[1 + d] += volume * x[d];
  };
  std::vector<char> failed;
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
  {
    if (static_cast<int>(b) == projectile)
      for (std::size_t i = p.begin_of(b); i < p.end_of(b); ++i)
        add_to_projectile(p.reference_position[i].cast<double>(), p.reference_volume[i]);
    // The target: every deformable body other than the projectile.
    if (static_cast<int>(b) == projectile || solver.body_material(b).is_rigid())
      continue;
    sample.has_target = true;
    const double half_spacing =
      0.5 * solver.scene().cell_size / solver.scene().bodies[b].particles_per_cell;
    sample.point_spacing = std::max(sample.point_spacing, 2.0 * half_spacing);
    for (std::size_t i = p.begin_of(b); i < p.end_of(b); ++i)
    {
      const mpm::Vector3 X = p.reference_position[i].cast<double>();
      extend(X, half_spacing);
      const std::uint8_t flag = p.failure[i];
      if (flag == 0)
      {
        ++sample.n_intact;
        sample.intact_volume += p.reference_volume[i];
      }
      else
        append_record(failed, X, p.reference_volume[i],
                      carries_no_deviatoric_stress(p.stress[i])
                        ? static_cast<std::uint8_t>(flag | debris_bit) : flag);
    }
  }
  // Target points that left the grid keep their place in the wound; a failed one carries no
  // stress any more, so it is debris.
  for (const mpm::DepartedPoint& d : solver.departed_points())
  {
    if (static_cast<int>(d.body) == projectile)
      add_to_projectile(d.reference_position, d.reference_volume);
    if (static_cast<int>(d.body) == projectile || solver.body_material(d.body).is_rigid())
      continue;
    const double half_spacing =
      0.5 * solver.scene().cell_size / solver.scene().bodies[d.body].particles_per_cell;
    extend(d.reference_position, half_spacing);
    if (d.failure == 0)
    {
      ++sample.n_intact;
      sample.intact_volume += d.reference_volume;
    }
    else
      append_record(failed, d.reference_position, d.reference_volume,
                    static_cast<std::uint8_t>(d.failure | debris_bit));
  }
  const mpm::RankGroup& ranks = solver.rank_group();
  double extremes[6] = {-lower[0], -lower[1], -lower[2], upper[0], upper[1], upper[2]};
  ranks.max(extremes, 6);
  sample.target_lower = mpm::Vector3(-extremes[0], -extremes[1], -extremes[2]);
  sample.target_upper = mpm::Vector3(extremes[3], extremes[4], extremes[5]);
  ranks.sum(projectile_sums, 4);
  if (projectile_sums[0] > 0.0)
    sample.projectile_origin =
      mpm::Vector3(projectile_sums[1], projectile_sums[2], projectile_sums[3]) / projectile_sums[0];
  sample.n_intact = ranks.sum(sample.n_intact);
  ranks.sum(&sample.intact_volume, 1);
  sample.n_points = ranks.sum(static_cast<std::uint64_t>(p.size()));

  append_gathered(sample, ranks, std::move(failed));
  return sample;
}

void add_failed_points(WoundSample& sample, const mpm::RankGroup& ranks,
                       const std::vector<FailedPoint>& points)
{
  std::vector<char> failed;
  for (const FailedPoint& point : points)
    append_record(failed, point.reference_position, point.reference_volume, point.failure);
  append_gathered(sample, ranks, std::move(failed));
}

void complete_by_mirrors(WoundSample& sample, const std::vector<mpm::SymmetryPlane>& planes)
{
  if (planes.empty())
    return;
  const std::size_t n = sample.failed_position.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const mpm::MirrorImages images = mpm::mirror_images(sample.failed_position[i], planes);
    for (int k = 1; k < images.count; ++k)
    {
      sample.failed_position.push_back(images.point[k]);
      sample.failed_volume.push_back(sample.failed_volume[i]);
      sample.failed_flag.push_back(sample.failed_flag[i]);
    }
  }
  const double copies = 1.0 / mpm::modelled_share(planes);
  sample.n_intact = static_cast<std::uint64_t>(std::llround(copies * sample.n_intact));
  sample.intact_volume *= copies;
  if (sample.has_target)
    mpm::mirror_box(sample.target_lower, sample.target_upper, planes);
  sample.projectile_origin = mpm::onto_planes(sample.projectile_origin, planes);
}

bool left_through_exit_face(const WoundSample& sample, const mpm::Solver& solver)
{
  const mpm::ProjectileExit& exit = solver.projectile_exit();
  if (!sample.has_target || solver.projectile() < 0 || !exit.recorded)
    return false;
  const PathThroughBox path = path_through_box(sample.target_lower, sample.target_upper,
                                               sample.projectile_origin, solver.flight_direction());
  if (!path.hits)
    return false;
  const int d = path.exit_face / 2;
  return path.exit_face % 2 == 1 ? exit.position[d] > sample.target_upper[d]
                                 : exit.position[d] < sample.target_lower[d];
}

namespace
{
/// The requested face layer (0: one cell) in whole rows of the target's points, so that the
/// failed volume over the depth is an area.
double face_layer_in_rows(const WoundSample& sample, const double cell_size,
                          const double face_layer)
{
  const double wanted = face_layer > 0.0 ? face_layer : cell_size;
  const double spacing = sample.point_spacing;
  return spacing > 0.0 ? spacing * std::max(1.0, std::round(wanted / spacing)) : wanted;
}
} // namespace

WoundMetrics wound_metrics_of(const WoundSample& sample, const mpm::Solver& solver,
                              const double face_layer, const double outline_grid)
{
  if (!sample.has_target)
  {
    WoundMetrics none;
    none.face_layer = face_layer_in_rows(sample, solver.scene().cell_size, face_layer);
    return none;
  }
  WoundGeometry geometry;
  geometry.box_lower = sample.target_lower;
  geometry.box_upper = sample.target_upper;
  geometry.path_origin = sample.projectile_origin;
  geometry.path_direction = solver.flight_direction();
  geometry.cell_size = solver.scene().cell_size;
  geometry.rings_about_path = solver.scene().axisymmetric;
  geometry.face_layer = face_layer_in_rows(sample, geometry.cell_size, face_layer);
  geometry.outline_spacing = outline_grid;
  // A scene without a projectile (a wave test) measures along the flight axis through its
  // middle; an exit wound needs a projectile that left.
  if (solver.projectile() < 0)
    geometry.path_origin = 0.5 * (sample.target_lower + sample.target_upper);
  geometry.projectile_exited = left_through_exit_face(sample, solver);
  // Intact points enter the metrics only through the intact count and volume.
  WoundMetrics m = compute_wound_metrics(sample.failed_position, sample.failed_volume,
                                         sample.failed_flag, geometry);
  m.counts[0] += sample.n_intact;
  m.volumes[0] += sample.intact_volume;
  return m;
}
} // namespace vulnus::analysis
