// Closed-form eigenvalues of a symmetric 3x3 matrix (trigonometric method, Smith 1961),
// used by the matrix failure criterion: no iterations, no eigenvectors.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace vulnus::materials
{
/// Eigenvalues of the symmetric matrix A (only its upper triangle is read), sorted
/// descending. With q = tr A / 3, p^2 = |A - q I|^2 / 6 and r = det((A - q I) / p) / 2:
/// e_k = q + 2 p cos(acos(r) / 3 + 2 pi k / 3). Absolute error about 1e-15 |A|.
inline Eigen::Vector3d symmetric_eigenvalues(const Eigen::Matrix3d& A)
{
  const double a00 = A(0, 0), a11 = A(1, 1), a22 = A(2, 2);
  const double a01 = A(0, 1), a02 = A(0, 2), a12 = A(1, 2);
  const double off = a01 * a01 + a02 * a02 + a12 * a12;
  const double q = (a00 + a11 + a22) / 3.0;
  const double d0 = a00 - q, d1 = a11 - q, d2 = a22 - q;
  const double p2 = (d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0;
  if (!(p2 > 1e-300))
    return Eigen::Vector3d(q, q, q);
  const double p = std::sqrt(p2);
  const double det_shifted =
      d0 * (d1 * d2 - a12 * a12) - a01 * (a01 * d2 - a12 * a02) + a02 * (a01 * a12 - d1 * a02);
  const double r = std::clamp(det_shifted / (2.0 * p2 * p), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  constexpr double two_pi_over_3 = 2.09439510239319549230842892218633526;
  const double e1 = q + 2.0 * p * std::cos(phi);
  const double e3 = q + 2.0 * p * std::cos(phi + two_pi_over_3);
  const double e2 = 3.0 * q - e1 - e3;
  return Eigen::Vector3d(e1, e2, e3);
}
} // namespace vulnus::materials
