// One cell's law evaluation and consistent stiffness, with or without the mean-dilatation F-bar.
#include "fem/cell_stiffness.h"

#include "fem/volume_averaged_cell.h"

#include <Eigen/LU>

namespace vulnus::fem
{
void CellStiffness::evaluate(const dealii::FEValues<3>& fe_values,
                             const std::vector<unsigned int>& component,
                             const std::vector<double>& u_local, const materials::Material& law,
                             const Eigen::Vector3d* fibers, materials::PointState* states,
                             const bool volume_averaging, const double time_step)
{
  const unsigned int n_q = fe_values.n_quadrature_points;
  const unsigned int n_dofs = static_cast<unsigned int>(u_local.size());
  F.resize(n_q);
  F_law.resize(n_q);
  P.resize(n_q);
  JxW.resize(n_q);
  responses.resize(n_q);
  grads.resize(std::size_t(n_q) * n_dofs);
  for (unsigned int q = 0; q < n_q; ++q)
  {
    F[q].setIdentity();
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const dealii::Tensor<1, 3> g = fe_values.shape_grad_component(i, q, component[i]);
      Eigen::Vector3d& grad = grads[std::size_t(q) * n_dofs + i];
      grad = Eigen::Vector3d(g[0], g[1], g[2]);
      F[q].row(component[i]) += u_local[i] * grad.transpose();
    }
    JxW[q] = fe_values.JxW(q);
  }
  double j_bar = 0.0;
  if (volume_averaging)
    j_bar = volume_averaged_gradients(int(n_q), F.data(), JxW.data(), F_law.data());
  else
    F_law = F;
  tangents.resize(n_q);
  sigma.resize(n_q);
  P_law.resize(n_q);
  for (unsigned int q = 0; q < n_q; ++q)
  {
    law.update(F_law[q], fibers[q], states[q], responses[q], time_step);
    tangents[q] = law.tangent(F_law[q], fibers[q], states[q], time_step);
    sigma[q] = responses[q].cauchy_stress;
    P_law[q] = F_law[q].determinant() * sigma[q] * F_law[q].inverse().transpose();
  }
  stiffness.setZero(n_dofs, n_dofs);
  if (volume_averaging)
  {
    volume_averaged_stresses(int(n_q), F.data(), JxW.data(), sigma.data(), j_bar, P.data());
    add_volume_averaged_stiffness(int(n_q), int(n_dofs), F.data(), JxW.data(), grads.data(),
                                  component.data(), tangents.data(), P_law.data(), 1.0, stiffness);
    return;
  }
  P = P_law;
  for (unsigned int q = 0; q < n_q; ++q)
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      // t_(cj L) = sum_J g_i[J] dP_(ci J)/dF_(cj L); K_ij = sum_L t_(cj L) g_j[L].
      const Eigen::Vector3d& gi = grads[std::size_t(q) * n_dofs + i];
      Eigen::Matrix<double, 9, 1> t =
          tangents[q].middleRows<3>(3 * component[i]).transpose() * gi;
      for (unsigned int j = 0; j < n_dofs; ++j)
        stiffness(i, j) +=
            JxW[q] * t.segment<3>(3 * component[j]).dot(grads[std::size_t(q) * n_dofs + j]);
    }
}

double CellStiffness::force(const unsigned int i, const unsigned int component_of_i) const
{
  const std::size_t n_dofs = grads.size() / F.size();
  double f = 0.0;
  for (std::size_t q = 0; q < F.size(); ++q)
    f += JxW[q] * P[q].row(component_of_i).dot(grads[q * n_dofs + i]);
  return f;
}
} // namespace vulnus::fem
