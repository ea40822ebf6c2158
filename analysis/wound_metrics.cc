// Wound metrics from failed points: volumes (by flag and of debris), the wounds of the faces
// the path crosses, the tract profiles along the path.
#include "analysis/wound_metrics.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

namespace vulnus::analysis
{
const char* box_face_name(const int face)
{
  static const char* const names[] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  return face >= 0 && face < 6 ? names[face] : "none";
}

bool carries_no_deviatoric_stress(const Eigen::Matrix<double, 6, 1>& stress)
{
  const double mean = (stress[0] + stress[1] + stress[2]) / 3.0;
  Eigen::Matrix<double, 6, 1> deviator = stress;
  for (int i = 0; i < 3; ++i)
    deviator[i] -= mean;
  // Shear entries count twice in the norm of the full tensor.
  const double dev2 = deviator.head<3>().squaredNorm() + 2.0 * deviator.tail<3>().squaredNorm();
  const double all2 = stress.head<3>().squaredNorm() + 2.0 * stress.tail<3>().squaredNorm();
  return dev2 <= 1e-20 * all2;
}

namespace
{
bool totally_failed(const std::uint8_t flag) { return (flag & 3u) == 3u; }

/// Totally failed points within `layer` inside `face` of the box.
FaceWound face_wound(const std::vector<Vector3>& x, const std::vector<double>& volume,
                     const std::vector<std::uint8_t>& flags, const WoundGeometry& g, const int face,
                     const double layer)
{
  FaceWound w;
  w.face = face;
  const int axis_index = face / 2;
  const bool lower_face = face % 2 == 0;
  const double plane = lower_face ? g.box_lower[axis_index] : g.box_upper[axis_index];
  const double inward = lower_face ? 1.0 : -1.0;
  if (g.outline_spacing > 0.0 && !g.rings_about_path)
    w.outline = face_outline(x, volume, flags, debris_bit, face, plane, layer, g.outline_spacing);
  auto in_layer = [&](const std::size_t p) {
    const double depth = inward * (x[p][axis_index] - plane);
    return totally_failed(flags[p]) && depth >= 0.0 && depth <= layer;
  };
  double total = 0.0;
  Vector3 mean = Vector3::Zero();
  for (std::size_t p = 0; p < x.size(); ++p)
    if (in_layer(p))
    {
      ++w.n_points;
      total += volume[p];
      mean += volume[p] * x[p];
    }
  if (w.n_points == 0)
    return w;
  mean /= total;
  w.area = total / layer;
  w.equivalent_diameter = std::sqrt(4.0 * w.area / M_PI);
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (std::size_t p = 0; p < x.size(); ++p)
    if (in_layer(p))
    {
      Vector3 r = x[p] - mean;
      r[axis_index] = 0.0;
      moments += volume[p] * r * r.transpose();
    }
  if (w.n_points < 3 || g.rings_about_path)
    return w;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(moments);
  // Eigenvalues ascending: [0] ~ 0 along the face normal, [1] minor, [2] major.
  const double minor = eigen.eigenvalues()[1], major = eigen.eigenvalues()[2];
  w.aspect_ratio = minor > 0.0 ? std::sqrt(major / minor) : 1.0;
  w.major_axis = eigen.eigenvectors().col(2);
  if (w.major_axis.maxCoeff() < -w.major_axis.minCoeff())
    w.major_axis = -w.major_axis; // sign convention: largest component positive
  return w;
}
} // namespace

WoundMetrics compute_wound_metrics(const std::vector<Vector3>& x, const std::vector<double>& volume,
                                   const std::vector<std::uint8_t>& flags, const WoundGeometry& g)
{
  WoundMetrics m;
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const unsigned flag = flags[p] & 3u;
    ++m.counts[flag];
    m.volumes[flag] += volume[p];
    if (flags[p] & debris_bit)
    {
      ++m.debris_count;
      m.debris_volume += volume[p];
    }
  }
  m.path = path_through_box(g.box_lower, g.box_upper, g.path_origin, g.path_direction);
  if (!m.path.hits)
    return m;
  m.face_layer = g.face_layer > 0.0 ? g.face_layer : g.cell_size;
  m.entrance = face_wound(x, volume, flags, g, m.path.entrance_face, m.face_layer);
  if (g.projectile_exited)
    m.exit = face_wound(x, volume, flags, g, m.path.exit_face, m.face_layer);

  const double h = g.cell_size;
  const std::size_t n_slices =
    // The box comes from single-precision reference positions: a 10 mm slab reads 10.0000002 mm,
    // which must not add an empty slice to the tract (it lowered the mean area by 1/n_slices).
    std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(m.path.length() / h - 1e-4)));
  m.tract_depth.resize(n_slices);
  m.tract_area.assign(n_slices, 0.0);
  m.debris_tract_area.assign(n_slices, 0.0);
  for (std::size_t s = 0; s < n_slices; ++s)
    m.tract_depth[s] = (s + 0.5) * h;
  const Vector3 entry = g.path_origin + m.path.t_in * g.path_direction;
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const bool debris = flags[p] & debris_bit;
    if (!totally_failed(flags[p]) && !debris)
      continue;
    const double depth = (x[p] - entry).dot(g.path_direction);
    if (depth < 0.0 || depth >= n_slices * h)
      continue;
    const std::size_t slice = static_cast<std::size_t>(depth / h);
    if (totally_failed(flags[p]))
      m.tract_area[slice] += volume[p] / h;
    if (debris)
      m.debris_tract_area[slice] += volume[p] / h;
  }
  return m;
}
} // namespace vulnus::analysis
