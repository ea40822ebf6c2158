// Conversions between deal.II tensors and the Eigen matrices of materials/ (one place, so
// the index convention A(i, j) = T[i][j] is written once).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <Eigen/Core>

namespace vulnus::fem
{
inline Eigen::Matrix3d to_eigen(const dealii::Tensor<2, 3>& t)
{
  Eigen::Matrix3d m;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      m(i, j) = t[i][j];
  return m;
}

inline Eigen::Vector3d to_eigen(const dealii::Tensor<1, 3>& t)
{
  return Eigen::Vector3d(t[0], t[1], t[2]);
}

inline dealii::Tensor<2, 3> to_dealii(const Eigen::Matrix3d& m)
{
  dealii::Tensor<2, 3> t;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      t[i][j] = m(i, j);
  return t;
}

inline dealii::Tensor<1, 3> to_dealii(const Eigen::Vector3d& v)
{
  dealii::Tensor<1, 3> t;
  for (unsigned int i = 0; i < 3; ++i)
    t[i] = v(i);
  return t;
}
} // namespace vulnus::fem
