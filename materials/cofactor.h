// The cofactor matrix of a 3x3 matrix, cof F = det(F) F^-T, without the division.
#pragma once

#include <Eigen/Core>

namespace vulnus::materials
{
template <typename Scalar>
Eigen::Matrix<Scalar, 3, 3> cofactor(const Eigen::Matrix<Scalar, 3, 3>& F)
{
  Eigen::Matrix<Scalar, 3, 3> c;
  c(0, 0) = F(1, 1) * F(2, 2) - F(1, 2) * F(2, 1);
  c(0, 1) = F(1, 2) * F(2, 0) - F(1, 0) * F(2, 2);
  c(0, 2) = F(1, 0) * F(2, 1) - F(1, 1) * F(2, 0);
  c(1, 0) = F(0, 2) * F(2, 1) - F(0, 1) * F(2, 2);
  c(1, 1) = F(0, 0) * F(2, 2) - F(0, 2) * F(2, 0);
  c(1, 2) = F(0, 1) * F(2, 0) - F(0, 0) * F(2, 1);
  c(2, 0) = F(0, 1) * F(1, 2) - F(0, 2) * F(1, 1);
  c(2, 1) = F(0, 2) * F(1, 0) - F(0, 0) * F(1, 2);
  c(2, 2) = F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0);
  return c;
}
} // namespace vulnus::materials
