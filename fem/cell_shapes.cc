// The explicit force pass's table of cell geometry: each distinct live cell shape's scalar
// shape-function gradients and JxW at the quadrature points, computed once with FEValues,
// and which node and component each cell dof moves.
#include "fem/far_field_data.h"

#include <deal.II/fe/fe_values.h>

#include <array>
#include <cmath>
#include <map>

namespace vulnus::fem
{
using namespace dealii;

namespace
{
constexpr unsigned int n_vertices = GeometryInfo<3>::vertices_per_cell;
using ShapeKey = std::array<long long, 3 * (n_vertices - 1)>;

/// The cell's vertex offsets from its first vertex, in units of 1e-10 of the cell's size:
/// equal keys mean translations of one cell to that tolerance.
ShapeKey shape_key(const DoFHandler<3>::active_cell_iterator& cell, const double size)
{
  const double unit = 1e-10 * size;
  ShapeKey key{};
  for (unsigned int v = 1; v < n_vertices; ++v)
  {
    const Tensor<1, 3> offset = cell->vertex(v) - cell->vertex(0);
    for (unsigned int d = 0; d < 3; ++d)
      key[3 * (v - 1) + d] = std::llround(offset[d] / unit);
  }
  return key;
}
} // namespace

void FarFieldSolver::Data::index_cell_shapes()
{
  const unsigned int n_dofs = fe.n_dofs_per_cell();
  const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
  dof_component = dof_components(fe);
  dof_node.resize(n_dofs);
  for (unsigned int i = 0; i < n_dofs; ++i)
    dof_node[i] = fe.system_to_component_index(i).second;

  cell_shapes.clear();
  live_cell_shape.resize(live_cells.size());
  std::map<ShapeKey, unsigned int> known;
  FEValues<3> fe_values(mapping, fe, quadrature, update_gradients | update_JxW_values);
  for (std::size_t c = 0; c < live_cells.size(); ++c)
  {
    const auto& cell = live_cells[c];
    const auto [entry, is_new] =
      known.emplace(shape_key(cell, cell_size[cell->active_cell_index()]),
                    static_cast<unsigned int>(cell_shapes.size()));
    live_cell_shape[c] = entry->second;
    if (!is_new)
      continue;
    fe_values.reinit(cell);
    CellShape shape;
    shape.gradients.resize(std::size_t(n_q_points) * n_nodes);
    shape.jxw.resize(n_q_points);
    for (unsigned int q = 0; q < n_q_points; ++q)
    {
      shape.jxw[q] = fe_values.JxW(q);
      for (unsigned int i = 0; i < n_dofs; ++i)
        if (dof_component[i] == 0)
        {
          const Tensor<1, 3> g = fe_values.shape_grad_component(i, q, 0);
          shape.gradients[q * n_nodes + dof_node[i]] = Eigen::Vector3d(g[0], g[1], g[2]);
        }
    }
    cell_shapes.push_back(std::move(shape));
  }
}
} // namespace vulnus::fem
