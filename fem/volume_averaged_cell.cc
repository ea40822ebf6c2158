// Mean-dilatation F-bar of one finite element cell: gradients, forces, consistent tangent.
#include "fem/volume_averaged_cell.h"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace vulnus::fem
{
double volume_averaged_gradients(const int n_q, const Eigen::Matrix3d* F, const double* w,
                                 Eigen::Matrix3d* F_bar)
{
  double volume = 0.0, weight = 0.0;
  for (int q = 0; q < n_q; ++q)
  {
    const double J = F[q].determinant();
    if (!(J > 0.0))
      throw std::runtime_error("deformation gradient with J = " + std::to_string(J) +
                               " (inverted element)");
    volume += w[q] * J;
    weight += w[q];
  }
  const double j_bar = volume / weight;
  for (int q = 0; q < n_q; ++q)
    F_bar[q] = std::cbrt(j_bar / F[q].determinant()) * F[q];
  return j_bar;
}

void volume_averaged_stresses(const int n_q, const Eigen::Matrix3d* F, const double* w,
                              const Eigen::Matrix3d* sigma_bar, const double j_bar,
                              Eigen::Matrix3d* P_eff)
{
  double pressure_integral = 0.0, volume = 0.0;
  for (int q = 0; q < n_q; ++q)
  {
    pressure_integral += w[q] * j_bar * sigma_bar[q].trace() / 3.0;
    volume += w[q] * F[q].determinant();
  }
  const double p = pressure_integral / volume;
  for (int q = 0; q < n_q; ++q)
  {
    const Eigen::Matrix3d tau = j_bar * sigma_bar[q];
    const Eigen::Matrix3d deviator = tau - (tau.trace() / 3.0) * Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d F_inverse_transpose = F[q].inverse().transpose();
    P_eff[q] = (deviator + p * F[q].determinant() * Eigen::Matrix3d::Identity()) *
               F_inverse_transpose;
  }
}

// With D_q[a] = e_(c_a) (x) g_a(q) the variation of F_q by dof a, g_q[a] = F_q^-T : D_q[a] the
// variation of ln J_q, h[a] = sum_r beta_r g_r[a] (beta_r = w_r J_r / sum w J) that of ln J_bar,
// e_q = h - g_q and alpha_q = (J_bar / J_q)^(1/3):
//   d F_bar_q[a] = alpha_q (D_q[a] + e_q[a] F_q / 3),
//   d2 F_bar_q[a, b] = d2 alpha F + (alpha / 3) (e[a] D[b] + e[b] D[a]),
//   d2 alpha[a, b] = alpha (e[a] e[b] / 9 + (dh[a, b] - dg_q[a, b]) / 3),
//   dg_q[a, b] = -m_q[a](c_b) m_q[b](c_a) with m_q[a] = F_q^-1 . g_a(q) (per component),
//   dh[a, b] = sum_r beta_r (g_r[a] g_r[b] + dg_r[a, b]) - h[a] h[b],
// and K_ab = sum_q w_q (dF_bar[a] : A_q : dF_bar[b] + P_bar_q : d2 F_bar_q[a, b]).
void add_volume_averaged_stiffness(const int n_q, const int n_dofs, const Eigen::Matrix3d* F,
                                   const double* w, const Eigen::Vector3d* grads,
                                   const unsigned int* component,
                                   const materials::Tangent* tangent,
                                   const Eigen::Matrix3d* P_bar, const double factor,
                                   Eigen::MatrixXd& K)
{
  std::vector<double> J(n_q), beta(n_q);
  std::vector<Eigen::Matrix3d> F_inverse(n_q);
  double volume = 0.0, weight = 0.0;
  for (int q = 0; q < n_q; ++q)
  {
    J[q] = F[q].determinant();
    F_inverse[q] = F[q].inverse();
    volume += w[q] * J[q];
    weight += w[q];
  }
  const double j_bar = volume / weight;
  for (int q = 0; q < n_q; ++q)
    beta[q] = w[q] * J[q] / volume;
  // m[q * n_dofs + a](c) = sum_J g_a(q)_J (F_q^-1)_(J c); g_q[a] = m(c_a).
  std::vector<Eigen::Vector3d> m(std::size_t(n_q) * n_dofs);
  Eigen::MatrixXd g(n_q, n_dofs);
  Eigen::VectorXd h = Eigen::VectorXd::Zero(n_dofs);
  for (int q = 0; q < n_q; ++q)
    for (int a = 0; a < n_dofs; ++a)
    {
      const Eigen::Vector3d mq = F_inverse[q].transpose() * grads[q * n_dofs + a];
      m[q * n_dofs + a] = mq;
      g(q, a) = mq[component[a]];
      h[a] += beta[q] * g(q, a);
    }
  // dh except the h h term: sum_r beta_r (g_r[a] g_r[b] + dg_r[a, b]).
  Eigen::MatrixXd dh = -h * h.transpose();
  for (int r = 0; r < n_q; ++r)
    for (int a = 0; a < n_dofs; ++a)
      for (int b = 0; b < n_dofs; ++b)
        dh(a, b) += beta[r] * (g(r, a) * g(r, b) -
                               m[r * n_dofs + a][component[b]] * m[r * n_dofs + b][component[a]]);

  Eigen::Matrix<double, 9, Eigen::Dynamic> B(9, n_dofs);
  Eigen::VectorXd e(n_dofs), t(n_dofs);
  for (int q = 0; q < n_q; ++q)
  {
    const double alpha = std::cbrt(j_bar / J[q]);
    const double s = (P_bar[q].array() * F[q].array()).sum();
    for (int a = 0; a < n_dofs; ++a)
    {
      const Eigen::Vector3d& ga = grads[q * n_dofs + a];
      const unsigned int c = component[a];
      e[a] = h[a] - g(q, a);
      t[a] = P_bar[q].row(c).dot(ga);
      // Row-major 9-vector of alpha (D + e F / 3): index 3 i + J.
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          B(3 * i + j, a) = alpha * ((i == int(c) ? ga[j] : 0.0) + e[a] * F[q](i, j) / 3.0);
    }
    K.noalias() += (factor * w[q]) * (B.transpose() * tangent[q] * B);
    for (int a = 0; a < n_dofs; ++a)
      for (int b = 0; b < n_dofs; ++b)
      {
        const double dg = -m[q * n_dofs + a][component[b]] * m[q * n_dofs + b][component[a]];
        const double d2_alpha = alpha * (e[a] * e[b] / 9.0 + (dh(a, b) - dg) / 3.0);
        K(a, b) += factor * w[q] * (s * d2_alpha + alpha / 3.0 * (e[a] * t[b] + e[b] * t[a]));
      }
  }
}
} // namespace vulnus::fem
