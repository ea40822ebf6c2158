// Hourglass stiffness of the one-point eight-node cell and the isotropic shear modulus that
// scales it.
#include "fem/hourglass.h"

namespace vulnus::fem
{
HourglassMatrix hourglass_stiffness(const Eigen::Vector3d* nodes,
                                    const Eigen::Vector3d* mean_gradients,
                                    const Eigen::Vector3d* point_gradients, const double* weights,
                                    const int n_q)
{
  constexpr int n_nodes = 8;
  // K_dev[(a,i),(b,j)] = sum_q w_q (delta_ij g_a.g_b + g_aj g_bi - 2/3 g_ai g_bj).
  HourglassMatrix K = HourglassMatrix::Zero();
  for (int q = 0; q < n_q; ++q)
    for (int a = 0; a < n_nodes; ++a)
      for (int b = 0; b < n_nodes; ++b)
      {
        const Eigen::Vector3d& ga = point_gradients[q * n_nodes + a];
        const Eigen::Vector3d& gb = point_gradients[q * n_nodes + b];
        const double dot = ga.dot(gb);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            K(3 * a + i, 3 * b + j) +=
              weights[q] * ((i == j ? dot : 0.0) + ga[j] * gb[i] - 2.0 / 3.0 * ga[i] * gb[j]);
      }
  // (L u)_(a,i) = sum_b u_bi (1/8 + g_b . (X_a - mean X)): the linear part of u.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int a = 0; a < n_nodes; ++a)
    mean += nodes[a] / n_nodes;
  HourglassMatrix P = HourglassMatrix::Identity();
  for (int a = 0; a < n_nodes; ++a)
    for (int b = 0; b < n_nodes; ++b)
    {
      const double l = 1.0 / n_nodes + mean_gradients[b].dot(nodes[a] - mean);
      for (int i = 0; i < 3; ++i)
        P(3 * a + i, 3 * b + i) -= l;
    }
  return P.transpose() * K * P;
}

double isotropic_shear_modulus(const materials::Tangent& tangent)
{
  double ijij = 0.0, iijj = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      ijij += tangent(3 * i + j, 3 * i + j);
      iijj += tangent(3 * i + i, 3 * j + j);
    }
  return (ijij - iijj / 3.0) / 10.0;
}
} // namespace vulnus::fem
