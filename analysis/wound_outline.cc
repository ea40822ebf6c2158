// Smoothed face-wound outline: quadratic B-spline projection of the debris indicator onto a
// fixed grid in the face plane, then the region above one half, sampled on subcells.
#include "analysis/wound_outline.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vulnus::analysis
{
namespace
{
/// Quadratic B-spline weights of the three nodes around s (in grid units), the first of them.
int quadratic_weights(const double s, double w[3])
{
  const int first = static_cast<int>(std::floor(s + 0.5)) - 1;
  for (int k = 0; k < 3; ++k)
  {
    const double r = std::abs(s - (first + k));
    w[k] = r < 0.5 ? 0.75 - r * r : r < 1.5 ? 0.5 * (1.5 - r) * (1.5 - r) : 0.0;
  }
  return first;
}
} // namespace

FaceOutline face_outline(const std::vector<Eigen::Vector3d>& x, const std::vector<double>& volume,
                         const std::vector<std::uint8_t>& flags, const std::uint8_t indicator_bit,
                         const int face, const double plane, const double layer,
                         const double spacing)
{
  FaceOutline out;
  out.grid_spacing = spacing;
  if (!(spacing > 0.0) || !(layer > 0.0))
    return out;
  const int normal = face / 2;
  const int a = (normal + 1) % 3, b = (normal + 2) % 3; // the face plane's axes
  const double inward = face % 2 == 0 ? 1.0 : -1.0;
  std::vector<std::size_t> in_layer;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (std::size_t p = 0; p < x.size(); ++p)
  {
    const double depth = inward * (x[p][normal] - plane);
    if (!(flags[p] & indicator_bit) || depth < 0.0 || depth > layer)
      continue;
    in_layer.push_back(p);
    lo[0] = std::min(lo[0], x[p][a]);
    lo[1] = std::min(lo[1], x[p][b]);
    hi[0] = std::max(hi[0], x[p][a]);
    hi[1] = std::max(hi[1], x[p][b]);
  }
  if (in_layer.empty())
    return out;
  // Nodes at integer multiples of H (a grid fixed in space, not to the points), two beyond
  // the points' extent on each side.
  const int i0 = static_cast<int>(std::floor(lo[0] / spacing)) - 2;
  const int j0 = static_cast<int>(std::floor(lo[1] / spacing)) - 2;
  const int ni = static_cast<int>(std::ceil(hi[0] / spacing)) + 3 - i0;
  const int nj = static_cast<int>(std::ceil(hi[1] / spacing)) + 3 - j0;
  std::vector<double> phi(static_cast<std::size_t>(ni) * nj, 0.0);
  const double full = spacing * spacing * layer;
  for (const std::size_t p : in_layer)
  {
    double wa[3], wb[3];
    const int fa = quadratic_weights(x[p][a] / spacing, wa) - i0;
    const int fb = quadratic_weights(x[p][b] / spacing, wb) - j0;
    for (int l = 0; l < 3; ++l)
      for (int k = 0; k < 3; ++k)
        phi[static_cast<std::size_t>(fb + l) * ni + fa + k] += wa[k] * wb[l] * volume[p] / full;
  }
  // The region phi >= 1/2, phi bilinear between nodes, counted on n x n subcells per cell.
  constexpr int n = 8;
  const double sub = spacing / n, sub_area = sub * sub;
  double area = 0.0;
  Eigen::Vector2d first = Eigen::Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (int j = 0; j + 1 < nj; ++j)
    for (int i = 0; i + 1 < ni; ++i)
    {
      const double p00 = phi[static_cast<std::size_t>(j) * ni + i];
      const double p10 = phi[static_cast<std::size_t>(j) * ni + i + 1];
      const double p01 = phi[static_cast<std::size_t>(j + 1) * ni + i];
      const double p11 = phi[static_cast<std::size_t>(j + 1) * ni + i + 1];
      if (std::max({p00, p10, p01, p11}) < 0.5)
        continue;
      for (int sj = 0; sj < n; ++sj)
        for (int si = 0; si < n; ++si)
        {
          const double u = (si + 0.5) / n, v = (sj + 0.5) / n;
          const double value = (1 - u) * (1 - v) * p00 + u * (1 - v) * p10 +
                               (1 - u) * v * p01 + u * v * p11;
          if (value < 0.5)
            continue;
          const Eigen::Vector2d c((i0 + i + u) * spacing, (j0 + j + v) * spacing);
          area += sub_area;
          first += sub_area * c;
          second += sub_area * c * c.transpose();
        }
    }
  if (area <= 0.0)
    return out;
  out.measured = true;
  out.area = area;
  out.equivalent_diameter = std::sqrt(4.0 * area / M_PI);
  const Eigen::Vector2d mean = first / area;
  const Eigen::Matrix2d moments = second / area - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(moments);
  const double minor = eigen.eigenvalues()[0], major = eigen.eigenvalues()[1];
  out.aspect_ratio = minor > 0.0 ? std::sqrt(major / minor) : 1.0;
  out.major_axis[a] = eigen.eigenvectors()(0, 1);
  out.major_axis[b] = eigen.eigenvectors()(1, 1);
  if (out.major_axis.maxCoeff() < -out.major_axis.minCoeff())
    out.major_axis = -out.major_axis; // sign convention: largest component positive
  return out;
}
} // namespace vulnus::analysis
