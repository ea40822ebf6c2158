// Visits the grid nodes a material point touches with their weight and weight gradient (and,
// for visitors that take it, the node's offset x_i - x_p), for linear, uGIMP or CPDI1 shape
// functions (compile-time choice so the loops unroll); a graded grid takes linear ones only,
// whose tents in cell units are the tents of its uneven nodes. CPDI reads the point's deformation
// gradient; the others ignore it.
#pragma once

#include "mpm/grid.h"
#include "mpm/shape_functions.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <array>
#include <limits>
#include <type_traits>

namespace vulnus::mpm
{
/// Gradient of the linear shape function of node `corner` (bits: +x, +y, +z) of a cell,
/// averaged over the cell.
inline Vector3 cell_mean_shape_gradient(const Grid& grid, const int corner)
{
  const int a = corner & 1, b = (corner >> 1) & 1, c = (corner >> 2) & 1;
  return 0.25 * grid.inverse_cell_size() * Vector3(2.0 * a - 1.0, 2.0 * b - 1.0, 2.0 * c - 1.0);
}

/// The layer of nodes an axisymmetric grid's points touch: the grid is one cell thick across
/// the r-y plane and nothing varies along it, so the plane's points give their whole weight to
/// the nodes on its z- face, and the z+ layer stays empty (half the nodes a 3D stencil visits).
inline constexpr int plane_node_layer = 0;

/// Keys of the 8 corners (in cell_mean_shape_gradient's order) of the cell whose lowest node
/// is `cell`; on an axisymmetric grid the z+ corners are their z- twins (plane_node_layer).
inline std::array<std::int64_t, 8> cell_corner_keys(const Grid& grid, const std::int64_t cell)
{
  const auto ijk = grid.node_ijk(cell);
  const int across = grid.axisymmetric() ? 0 : 1;
  std::array<std::int64_t, 8> keys;
  for (int corner = 0; corner < 8; ++corner)
    keys[corner] = grid.node_key(ijk[0] + (corner & 1), ijk[1] + ((corner >> 1) & 1),
                                 ijk[2] + across * ((corner >> 2) & 1));
  return keys;
}

namespace detail
{
template <class Visitor>
inline void visit_node(const Grid& grid, const Vector3& s, const Vector3& cell_widths, const int i,
                       const int j, const int k, const double weight, const Vector3& gradient,
                       Visitor& visit)
{
  const std::int64_t key = grid.node_key(i, j, k);
  if constexpr (std::is_invocable_v<Visitor, std::int64_t, double, const Vector3&, const Vector3&>)
  {
    // Node i is a corner of the point's cell along each axis on a graded grid (linear shape
    // functions), so its offset is in that cell's widths.
    const Vector3 offset(i - s[0], j - s[1], k - s[2]);
    visit(key, weight, gradient, cell_widths.cwiseProduct(offset).eval());
  }
  else
    visit(key, weight, gradient);
}

/// CPDI1: the point's parallelepiped x_p + sum_k xi_k r_k (xi in [-1, 1]^3) carries the
/// trilinear interpolant of each node's tent function through its 8 corners, so the weight is
/// the corners' mean, w_i = 1/8 sum_c N_i(x_c), and the domain-averaged gradient is
/// 1/8 sum_c N_i(x_c) R^-T s_c (s_c the corner's signs, R = [r_1 r_2 r_3]). The corners'
/// shares are summed per node in the block of nodes the corners' cells span (at most
/// 4 x 4 x 4 within the reach) before any node is visited, so a node shared by several
/// corners is scattered to once.
template <class Visitor>
inline Vector3 for_each_cpdi_node(const Grid& grid, const double lp, const Vector3& x,
                               const Eigen::Matrix3d& F, Visitor& visit)
{
  constexpr int most = 4;
  const Eigen::Matrix3d r = cpdi_half_vectors(F, lp);
  const Eigen::Matrix3d gradient_map = r.inverse().transpose() * (0.125 * grid.inverse_cell_size());
  const Vector3 s = grid.to_cell_units(x);
  AxisWeights w[8][3];
  int lo[3] = {std::numeric_limits<int>::max(), std::numeric_limits<int>::max(),
               std::numeric_limits<int>::max()};
  int hi[3] = {std::numeric_limits<int>::min(), std::numeric_limits<int>::min(),
               std::numeric_limits<int>::min()};
  for (int c = 0; c < 8; ++c)
  {
    const Vector3 corner = cpdi_corner(s, r, c);
    for (int d = 0; d < 3; ++d)
    {
      linear_axis_weights(corner[d], 1.0, w[c][d]);
      lo[d] = std::min(lo[d], w[c][d].first_node);
      hi[d] = std::max(hi[d], w[c][d].first_node);
    }
  }
  // A corner exactly on the reach's last node has a zero second weight, never stored.
  int n[3];
  for (int d = 0; d < 3; ++d)
    n[d] = std::min(most, hi[d] - lo[d] + 2);
  const int entries = n[0] * n[1] * n[2];
  std::array<double, most * most * most> weight;
  std::array<Vector3, most * most * most> gradient;
  for (int e = 0; e < entries; ++e)
  {
    weight[e] = 0.0;
    gradient[e].setZero();
  }
  for (int c = 0; c < 8; ++c)
  {
    const Vector3 corner_gradient =
      gradient_map * Vector3(corner_sign(c, 0), corner_sign(c, 1), corner_sign(c, 2));
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
        {
          const double N = w[c][0].value[i] * w[c][1].value[j] * w[c][2].value[k];
          if (N == 0.0)
            continue;
          const int entry = (w[c][0].first_node + i - lo[0]) +
                            n[0] * ((w[c][1].first_node + j - lo[1]) +
                                    n[1] * (w[c][2].first_node + k - lo[2]));
          weight[entry] += 0.125 * N;
          gradient[entry] += N * corner_gradient;
        }
  }
  const Vector3 widths = Vector3::Constant(grid.cell_size()); // CPDI runs on uniform grids
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const int entry = i + n[0] * (j + n[1] * k);
        if (weight[entry] == 0.0)
          continue;
        visit_node(grid, s, widths, lo[0] + i, lo[1] + j, lo[2] + k, weight[entry], gradient[entry],
                   visit);
      }
  return s;
}
} // namespace detail

/// The blocks of nodes a point's stencil may touch, each given by its first node, its width
/// along x and y and its depth along z, for the node marking: one block of nodes_per_axis
/// nodes from the first stencil node (linear, GIMP; one layer deep on an axisymmetric grid),
/// or the 2 x 2 x 2 nodes of each corner's cell (CPDI).
template <class Visit>
inline void for_each_stencil_block(const Grid& grid, const ShapeFunction shape, const double lp,
                                   const Vector3& x, const Eigen::Matrix3d& F, Visit&& visit)
{
  const Vector3 s = grid.to_cell_units(x);
  if (shape != ShapeFunction::cpdi)
  {
    const int n = nodes_per_axis(shape);
    const bool plane = grid.axisymmetric();
    visit(std::array<int, 3>{{first_stencil_node(s[0], lp), first_stencil_node(s[1], lp),
                              plane ? plane_node_layer : first_stencil_node(s[2], lp)}},
          n, plane ? 1 : n);
    return;
  }
  const Eigen::Matrix3d r = cpdi_half_vectors(F, lp);
  for (int c = 0; c < 8; ++c)
  {
    const Vector3 corner = cpdi_corner(s, r, c);
    visit(std::array<int, 3>{{first_stencil_node(corner[0], 0.0), first_stencil_node(corner[1], 0.0),
                              first_stencil_node(corner[2], 0.0)}},
          2, 2);
  }
}

/// Visits the nodes of the point at x; returns x in cell units (Grid::to_cell_units).
template <ShapeFunction shape, class Visitor>
inline Vector3 for_each_node(const Grid& grid, const double half_size_cells, const Vector3& x,
                             const Eigen::Matrix3d& F, Visitor&& visit)
{
  if constexpr (shape == ShapeFunction::cpdi)
  {
    return detail::for_each_cpdi_node(grid, half_size_cells, x, F, visit);
  }
  else
  {
    constexpr int n = nodes_per_axis(shape);
    const double inverse_h = grid.inverse_cell_size();
    Vector3 widths, inverse_widths;
    const Vector3 s = grid.locate(x, widths, inverse_widths);
    AxisWeights w[3];
    for (int d = 0; d < 3; ++d)
    {
      if constexpr (shape == ShapeFunction::linear)
        linear_axis_weights(s[d], inverse_widths[d], w[d]);
      else
        gimp_axis_weights(s[d], half_size_cells, inverse_h, w[d]);
    }
    // The r-y plane's third axis is the hoop direction: nothing varies along it, and one
    // layer of nodes carries the plane (plane_node_layer).
    int layers = n;
    if (grid.axisymmetric())
    {
      layers = 1;
      w[2].first_node = plane_node_layer;
      w[2].value[0] = 1.0;
      w[2].derivative[0] = 0.0;
    }
    for (int k = 0; k < layers; ++k)
      for (int j = 0; j < n; ++j)
      {
        const double wjk = w[1].value[j] * w[2].value[k];
        const double djk = w[1].derivative[j] * w[2].value[k];
        const double wjdk = w[1].value[j] * w[2].derivative[k];
        for (int i = 0; i < n; ++i)
        {
          const double weight = w[0].value[i] * wjk;
          if (weight == 0.0 && w[0].derivative[i] == 0.0)
            continue;
          const Vector3 gradient(w[0].derivative[i] * wjk, w[0].value[i] * djk,
                                 w[0].value[i] * wjdk);
          detail::visit_node(grid, s, widths, w[0].first_node + i, w[1].first_node + j,
                             w[2].first_node + k, weight, gradient, visit);
        }
      }
    return s;
  }
}

/// Runtime dispatch helper: calls f with the shape as a compile-time constant.
template <class F>
inline void with_shape(const ShapeFunction shape, F&& f)
{
  if (shape == ShapeFunction::linear)
    f(std::integral_constant<ShapeFunction, ShapeFunction::linear>());
  else if (shape == ShapeFunction::gimp)
    f(std::integral_constant<ShapeFunction, ShapeFunction::gimp>());
  else
    f(std::integral_constant<ShapeFunction, ShapeFunction::cpdi>());
}
} // namespace vulnus::mpm
