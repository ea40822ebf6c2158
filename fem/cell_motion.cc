// The best-fit affine motion of a hexahedral cell and what is left of its nodes' motion.
#include "fem/cell_motion.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vulnus::fem
{
namespace
{
/// Corner a's Jacobian of the trilinear map through the nodes x: its three edges, each taken
/// in the direction of increasing reference coordinate.
double corner_jacobian(const CellNodes& x, const int a)
{
  Eigen::Matrix3d edges;
  for (int d = 0; d < 3; ++d)
  {
    const int neighbour = a ^ (1 << d);
    const double sign = (a >> d) & 1 ? -1.0 : 1.0;
    edges.col(d) = sign * (x[neighbour] - x[a]);
  }
  return edges.determinant();
}
} // namespace

CellMotion cell_motion(const CellNodes& X, const CellNodes& u, const double size)
{
  Eigen::Vector3d X_mean = Eigen::Vector3d::Zero(), u_mean = Eigen::Vector3d::Zero();
  for (int a = 0; a < 8; ++a)
  {
    X_mean += X[a] / 8.0;
    u_mean += u[a] / 8.0;
  }
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero(), moved = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a)
  {
    const Eigen::Vector3d dX = X[a] - X_mean;
    spread += dX * dX.transpose();
    moved += (u[a] - u_mean) * dX.transpose();
  }
  const Eigen::Matrix3d H = moved * spread.inverse(); // least squares: u - u_mean = H dX
  CellMotion m;
  m.gradient = Eigen::Matrix3d::Identity() + H;
  for (int a = 0; a < 8; ++a)
    m.non_affine =
      std::max(m.non_affine, ((u[a] - u_mean) - H * (X[a] - X_mean)).norm() / size);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> squares(m.gradient.transpose() *
                                                               m.gradient);
  const Eigen::Vector3d lambda2 = squares.eigenvalues(); // ascending
  m.deviatoric_stretch = lambda2[0] > 0.0 ? 0.5 * std::log(lambda2[2] / lambda2[0])
                                          : std::numeric_limits<double>::infinity();
  CellNodes x;
  for (int a = 0; a < 8; ++a)
    x[a] = X[a] + u[a];
  double smallest = std::numeric_limits<double>::infinity();
  double largest = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < 8; ++a)
  {
    const double J = corner_jacobian(x, a);
    smallest = std::min(smallest, J);
    largest = std::max(largest, J);
  }
  m.jacobian_ratio = largest > 0.0 ? smallest / largest : -1.0;
  return m;
}
} // namespace vulnus::fem
