// One quadrature point's share of an implicit step's Newton matrix:
// stiffness_factor K + mass_factor M, with K from the material tangent dP/dF.
#pragma once

#include "materials/material.h"

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace vulnus::fem
{
/// Adds the point's share to cell_matrix: grads and values are the shape functions' gradients
/// and values of each cell dof's component (component[i]) at the point, JxW its weight.
inline void add_point_tangent(const materials::Tangent& tangent,
                              const std::vector<dealii::Tensor<1, 3>>& grads,
                              const std::vector<double>& values,
                              const std::vector<unsigned int>& component, const double JxW,
                              const double density, const double stiffness_factor,
                              const double mass_factor, dealii::FullMatrix<double>& cell_matrix)
{
  const unsigned int n_dofs = static_cast<unsigned int>(grads.size());
  const double rho_JxW = density * JxW;
  for (unsigned int i = 0; i < n_dofs; ++i)
  {
    const unsigned int ci = component[i];
    // t_iL = sum_J g_i[J] dP_{ci J}/dF_{cj L}, then K_ij = t_i(cj, :) . g_j.
    double t_i[3][3];
    for (unsigned int cj = 0; cj < 3; ++cj)
      for (unsigned int L = 0; L < 3; ++L)
      {
        double s = 0.0;
        for (unsigned int J = 0; J < 3; ++J)
          s += grads[i][J] * tangent(3 * ci + J, 3 * cj + L);
        t_i[cj][L] = s;
      }
    for (unsigned int j = 0; j < n_dofs; ++j)
    {
      const unsigned int cj = component[j];
      const double kij =
          t_i[cj][0] * grads[j][0] + t_i[cj][1] * grads[j][1] + t_i[cj][2] * grads[j][2];
      cell_matrix(i, j) += stiffness_factor * kij * JxW +
                           (ci == cj ? mass_factor * rho_JxW * values[i] * values[j] : 0.0);
    }
  }
}
} // namespace vulnus::fem
