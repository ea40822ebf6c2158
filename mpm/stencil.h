// Visits the grid nodes a material point touches with their weight and weight gradient (and,
// for visitors that take it, the node's offset x_i - x_p), for linear or uGIMP shape
// functions (compile-time choice so the loops unroll).
#pragma once

#include "mpm/grid.h"
#include "mpm/shape_functions.h"

#include <type_traits>

namespace vulnus::mpm
{
template <ShapeFunction shape, class Visitor>
inline void for_each_node(const Grid& grid, const double half_size_cells, const Vector3& x,
                          Visitor&& visit)
{
  constexpr int n = nodes_per_axis(shape);
  const Vector3 s = grid.to_cell_units(x);
  const double inverse_h = grid.inverse_cell_size();
  AxisWeights w[3];
  for (int d = 0; d < 3; ++d)
  {
    if constexpr (shape == ShapeFunction::linear)
      linear_axis_weights(s[d], inverse_h, w[d]);
    else
      gimp_axis_weights(s[d], half_size_cells, inverse_h, w[d]);
  }
  for (int k = 0; k < n; ++k)
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
        const std::int64_t key =
            grid.node_key(w[0].first_node + i, w[1].first_node + j, w[2].first_node + k);
        if constexpr (std::is_invocable_v<Visitor, std::int64_t, double, const Vector3&,
                                          const Vector3&>)
        {
          const Vector3 offset(w[0].first_node + i - s[0], w[1].first_node + j - s[1],
                               w[2].first_node + k - s[2]);
          visit(key, weight, gradient, (grid.cell_size() * offset).eval());
        }
        else
          visit(key, weight, gradient);
      }
    }
}

/// Runtime dispatch helper: calls f with the shape as a compile-time constant.
template <class F>
inline void with_shape(const ShapeFunction shape, F&& f)
{
  if (shape == ShapeFunction::linear)
    f(std::integral_constant<ShapeFunction, ShapeFunction::linear>());
  else
    f(std::integral_constant<ShapeFunction, ShapeFunction::gimp>());
}
} // namespace vulnus::mpm
