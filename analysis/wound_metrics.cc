// Wound metrics from failed points: volumes, face wounds, tract profile.
#include "analysis/wound_metrics.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace vulnus::analysis
{
namespace
{
FaceWound face_wound(const std::vector<Vector3>& x, const std::vector<double>& volume,
                     const std::vector<std::uint8_t>& flags, const Vector3& axis,
                     const double plane, const double inward, const double cell_size)
{
  FaceWound w;
  double total = 0.0;
  Vector3 mean = Vector3::Zero();
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const double depth = inward * (x[p].dot(axis) - plane);
    if (flags[p] != 3 || depth < 0.0 || depth > cell_size)
      continue;
    ++w.n_points;
    total += volume[p];
    mean += volume[p] * x[p];
  }
  if (w.n_points == 0)
    return w;
  mean /= total;
  w.area = total / cell_size;
  w.equivalent_diameter = std::sqrt(4.0 * w.area / M_PI);
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d in_plane = Eigen::Matrix3d::Identity() - axis * axis.transpose();
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const double depth = inward * (x[p].dot(axis) - plane);
    if (flags[p] != 3 || depth < 0.0 || depth > cell_size)
      continue;
    const Vector3 r = in_plane * (x[p] - mean);
    moments += volume[p] * r * r.transpose();
  }
  if (w.n_points < 3)
    return w;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(moments);
  // Eigenvalues ascending: [0] ~ 0 along the axis, [1] minor, [2] major.
  const double minor = eigen.eigenvalues()[1], major = eigen.eigenvalues()[2];
  w.aspect_ratio = minor > 0.0 ? std::sqrt(major / minor) : 1.0;
  w.major_axis = eigen.eigenvectors().col(2);
  if (w.major_axis.maxCoeff() < -w.major_axis.minCoeff())
    w.major_axis = -w.major_axis; // sign convention: largest component positive
  return w;
}
} // namespace

WoundMetrics compute_wound_metrics(const std::vector<Vector3>& x, const std::vector<double>& volume,
                                   const std::vector<std::uint8_t>& flags, const Vector3& axis,
                                   const double entrance, const double exit, const double cell_size)
{
  WoundMetrics m;
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const unsigned flag = flags[p] & 3u;
    ++m.counts[flag];
    m.volumes[flag] += volume[p];
  }
  m.entrance = face_wound(x, volume, flags, axis, entrance, +1.0, cell_size);
  m.exit = face_wound(x, volume, flags, axis, exit, -1.0, cell_size);

  const std::size_t n_slices = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((exit - entrance) / cell_size - 1e-9)));
  m.tract_depth.resize(n_slices);
  m.tract_area.assign(n_slices, 0.0);
  for (std::size_t s = 0; s < n_slices; ++s)
    m.tract_depth[s] = (s + 0.5) * cell_size;
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    if (flags[p] != 3)
      continue;
    const double depth = x[p].dot(axis) - entrance;
    if (depth < 0.0 || depth >= n_slices * cell_size)
      continue;
    m.tract_area[static_cast<std::size_t>(depth / cell_size)] += volume[p] / cell_size;
  }
  return m;
}
} // namespace vulnus::analysis
