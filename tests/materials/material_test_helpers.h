// Helpers shared by the material tests: random deformations and rotations, finite differences.
#pragma once

#include "materials/material.h"

#include <Eigen/Geometry>

#include <functional>
#include <random>

namespace vulnus::materials::testing
{
inline Tensor2 random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// F = I + amplitude * random matrix, re-drawn until det F > 0.2.
inline Tensor2 random_deformation(std::mt19937& rng, const double amplitude)
{
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  while (true)
  {
    Tensor2 F = Tensor2::Identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        F(i, j) += amplitude * uniform(rng);
    if (F.determinant() > 0.2)
      return F;
  }
}

inline Vector3 random_unit_vector(std::mt19937& rng)
{
  std::normal_distribution<double> normal(0.0, 1.0);
  return Vector3(normal(rng), normal(rng), normal(rng)).normalized();
}

/// Isochoric uniaxial stretch l along the unit vector a.
inline Tensor2 isochoric_uniaxial(const double l, const Vector3& a)
{
  const Tensor2 aa = a * a.transpose();
  return l * aa + (Tensor2::Identity() - aa) / std::sqrt(l);
}

/// Central finite-difference derivative of a scalar function of F: dW/dF_ij.
inline Tensor2 finite_difference_gradient(const std::function<double(const Tensor2&)>& W,
                                          const Tensor2& F, const double h)
{
  Tensor2 gradient;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      Tensor2 plus = F, minus = F;
      plus(i, j) += h;
      minus(i, j) -= h;
      gradient(i, j) = (W(plus) - W(minus)) / (2.0 * h);
    }
  return gradient;
}

/// Central finite-difference dP/dF in the layout of Tangent (row 3i+J, column 3k+L).
inline Tangent finite_difference_tangent(const std::function<Tensor2(const Tensor2&)>& P,
                                         const Tensor2& F, const double h)
{
  Tangent D;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
      Tensor2 plus = F, minus = F;
      plus(k, L) += h;
      minus(k, L) -= h;
      const Tensor2 dP = (P(plus) - P(minus)) / (2.0 * h);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          D(3 * i + j, 3 * k + L) = dP(i, j);
    }
  return D;
}

/// First Piola stress from a Cauchy stress: P = J sigma F^{-T}.
inline Tensor2 first_piola(const Tensor2& sigma, const Tensor2& F)
{
  return F.determinant() * sigma * F.inverse().transpose();
}
} // namespace vulnus::materials::testing
