// MPM shape functions evaluated per particle: linear (tent, 2 nodes per axis), uGIMP
// (generalized interpolation with a constant particle half-size, 3 nodes per axis) and CPDI1
// (the particle's domain a parallelepiped that deforms with it; Sadeghirad, Brannon and
// Burghardt 2011). Header-only so the transfer kernels inline them.
#pragma once

#include "mpm/scene_parameters.h"

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>

namespace vulnus::mpm
{
/// Weights and derivatives of the nodes a particle touches along one axis.
struct AxisWeights
{
  int first_node = 0; ///< grid index of the first node
  std::array<double, 3> value{};
  std::array<double, 3> derivative{}; ///< d value / d x_particle
};

/// First node along one axis of the stencil of a point at s (cell units), half-size lp in
/// cells (0 for linear shape functions). The node marking and the transfers must agree on it.
inline int first_stencil_node(const double s, const double lp)
{
  return static_cast<int>(std::floor(s - lp));
}

/// Linear tent function: s = (x - x_min) / h, nodes floor(s) and floor(s) + 1.
inline void linear_axis_weights(const double s, const double inverse_h, AxisWeights& w)
{
  w.first_node = first_stencil_node(s, 0.0);
  const double xi = s - w.first_node;
  w.value[0] = 1.0 - xi;
  w.value[1] = xi;
  w.value[2] = 0.0;
  w.derivative[0] = -inverse_h;
  w.derivative[1] = inverse_h;
  w.derivative[2] = 0.0;
}

/// uGIMP 1D weight of a node at signed distance r = x_p - x_i (in cells), particle
/// half-size lp (in cells, lp <= 1/2): Bardenhagen & Kober 2004, eq. for the
/// convolution of the tent function with a box of width 2 lp.
inline void gimp_node_weight(const double r, const double lp, double& value, double& slope)
{
  const double a = std::abs(r);
  const double sign = r < 0.0 ? -1.0 : 1.0;
  if (a < lp)
  {
    value = 1.0 - (r * r + lp * lp) / (2.0 * lp);
    slope = -r / lp;
  }
  else if (a < 1.0 - lp)
  {
    value = 1.0 - a;
    slope = -sign;
  }
  else if (a < 1.0 + lp)
  {
    const double d = 1.0 + lp - a;
    value = d * d / (4.0 * lp);
    slope = -sign * d / (2.0 * lp);
  }
  else
  {
    value = 0.0;
    slope = 0.0;
  }
}

/// GIMP along one axis: s = (x - x_min) / h, lp particle half-size in cells.
inline void gimp_axis_weights(const double s, const double lp, const double inverse_h,
                              AxisWeights& w)
{
  const int first = first_stencil_node(s, lp);
  w.first_node = first;
  for (int k = 0; k < 3; ++k)
  {
    double value, slope;
    gimp_node_weight(s - (first + k), lp, value, slope);
    w.value[k] = value;
    w.derivative[k] = slope * inverse_h;
  }
}

/// Number of nodes per axis touched by a particle (linear and GIMP; a CPDI point touches the
/// nodes of its corners' cells).
inline constexpr int nodes_per_axis(const ShapeFunction shape)
{
  return shape == ShapeFunction::linear ? 2 : 3;
}

/// Most (node, weight) entries a point's stencil visits: a CPDI point's corners stay within a
/// cell of it, so its nodes lie in a 4 x 4 x 4 block.
inline constexpr int stencil_entries(const ShapeFunction shape)
{
  return shape == ShapeFunction::cpdi ? 64 : nodes_per_axis(shape) * nodes_per_axis(shape) *
                                               nodes_per_axis(shape);
}

/// A CPDI corner reaches at most this many cells from its point along any axis, so the
/// stencil spans the nodes GIMP's does (floor(s) - 1 .. floor(s) + 2) and the grid padding,
/// the rank seams and the share seams need nothing more.
inline constexpr double cpdi_reach_cells = 1.0;

/// CPDI1 domain of a point, in cell units: the columns are the half-vectors r_k = F (lp e_k)
/// of its parallelepiped (lp its reference half-size in cells). A domain stretched beyond the
/// reach along some axis is shrunk uniformly to just inside it (as Uintah's cpdi_lcrit does).
/// One with det F <= 0 or a non-finite F, which no material state should have, falls back to
/// the reference box, so that no corner can leave the 4 x 4 x 4 node block.
inline Eigen::Matrix3d cpdi_half_vectors(const Eigen::Matrix3d& F, const double lp)
{
  constexpr double largest_extent = cpdi_reach_cells * (1.0 - 1e-9);
  Eigen::Matrix3d r = lp * F;
  const double extent = r.cwiseAbs().rowwise().sum().maxCoeff();
  if (!(F.determinant() > 0.0) || !std::isfinite(extent))
    return lp * Eigen::Matrix3d::Identity();
  if (extent > largest_extent)
    r *= largest_extent / extent;
  return r;
}

/// Sign of corner c (0..7) along axis d: bit d of c set is +1.
inline constexpr double corner_sign(const int c, const int d)
{
  return ((c >> d) & 1) ? 1.0 : -1.0;
}

/// Corner c of a CPDI domain with half-vectors r around s (cell units). The node marking and
/// the transfers both place corners through it, so they agree on every corner's cell.
inline Eigen::Vector3d cpdi_corner(const Eigen::Vector3d& s, const Eigen::Matrix3d& r, const int c)
{
  return s + r * Eigen::Vector3d(corner_sign(c, 0), corner_sign(c, 1), corner_sign(c, 2));
}

} // namespace vulnus::mpm
