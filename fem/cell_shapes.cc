// The explicit force pass's table of cell geometry: each distinct live cell shape's scalar
// shape-function gradients and JxW at the quadrature points, computed once with FEValues,
// and which node and component each cell dof moves; with one-point integration each shape's
// mean gradients and hourglass stiffness instead.
#include "fem/far_field_data.h"
#include "fem/hourglass.h"

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

/// One-point integration's geometry of a Q1 cell (Flanagan and Belytschko 1981): the mean
/// shape-function gradients (1 / V) int grad N_a dV, exact with the full rule, so the
/// forces of a constant stress cancel between neighbours on distorted meshes as well (the
/// patch test), and the hourglass stiffness per unit shear modulus in cell dof order.
void one_point_shape(const DoFHandler<3>::active_cell_iterator& cell, FEValues<3>& full,
                     const std::vector<unsigned int>& dof_node,
                     const std::vector<unsigned int>& dof_component,
                     FarFieldSolver::Data::CellShape& shape)
{
  const unsigned int n_dofs = dof_node.size();
  const unsigned int n_q = full.n_quadrature_points;
  std::array<Eigen::Vector3d, n_vertices> nodes, mean;
  std::vector<Eigen::Vector3d> point_gradients(std::size_t(n_q) * n_vertices);
  std::vector<double> weights(n_q);
  full.reinit(cell);
  double volume = 0.0;
  for (unsigned int q = 0; q < n_q; ++q)
    volume += weights[q] = full.JxW(q);
  for (unsigned int i = 0; i < n_dofs; ++i)
    if (dof_component[i] == 0)
    {
      const unsigned int a = dof_node[i]; // Q1: shape function a belongs to vertex a
      const Point<3>& x = cell->vertex(a);
      nodes[a] = Eigen::Vector3d(x[0], x[1], x[2]);
      mean[a].setZero();
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const Tensor<1, 3> g = full.shape_grad_component(i, q, 0);
        point_gradients[q * n_vertices + a] = Eigen::Vector3d(g[0], g[1], g[2]);
        mean[a] += weights[q] / volume * point_gradients[q * n_vertices + a];
      }
    }
  shape.gradients.assign(mean.begin(), mean.end());
  shape.jxw.assign(1, volume);
  const HourglassMatrix S = hourglass_stiffness(nodes.data(), mean.data(), point_gradients.data(),
                                                weights.data(), int(n_q));
  shape.hourglass.resize(std::size_t(n_dofs) * n_dofs);
  for (unsigned int i = 0; i < n_dofs; ++i)
    for (unsigned int j = 0; j < n_dofs; ++j)
      shape.hourglass[i * n_dofs + j] =
        S(3 * dof_node[i] + dof_component[i], 3 * dof_node[j] + dof_component[j]);
}
/// The full rule's gradients and JxW at every point of the cell.
void full_rule_shape(const DoFHandler<3>::active_cell_iterator& cell, FEValues<3>& fe_values,
                     const std::vector<unsigned int>& dof_node,
                     const std::vector<unsigned int>& dof_component, const unsigned int n_nodes,
                     FarFieldSolver::Data::CellShape& shape)
{
  const unsigned int n_q = fe_values.n_quadrature_points;
  fe_values.reinit(cell);
  shape.gradients.resize(std::size_t(n_q) * n_nodes);
  shape.jxw.resize(n_q);
  for (unsigned int q = 0; q < n_q; ++q)
  {
    shape.jxw[q] = fe_values.JxW(q);
    for (unsigned int i = 0; i < dof_node.size(); ++i)
      if (dof_component[i] == 0)
      {
        const Tensor<1, 3> g = fe_values.shape_grad_component(i, q, 0);
        shape.gradients[q * n_nodes + dof_node[i]] = Eigen::Vector3d(g[0], g[1], g[2]);
      }
  }
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
  const bool one_point = prm.one_point_integration;
  // One point takes its mean gradients and hourglass stiffness from the full rule.
  FEValues<3> fe_values(mapping, fe, one_point ? mass_quadrature : quadrature,
                        update_gradients | update_JxW_values);
  hourglass_modulus = 0.0;
  if (one_point)
    hourglass_modulus =
      prm.hourglass_coefficient *
      isotropic_shear_modulus(material->tangent(Eigen::Matrix3d::Identity(),
                                                Eigen::Vector3d::UnitX(), materials::PointState()));
  for (std::size_t c = 0; c < live_cells.size(); ++c)
  {
    const auto& cell = live_cells[c];
    const auto [entry, is_new] =
      known.emplace(shape_key(cell, cell_size[cell->active_cell_index()]),
                    static_cast<unsigned int>(cell_shapes.size()));
    live_cell_shape[c] = entry->second;
    if (!is_new)
      continue;
    CellShape shape;
    if (one_point)
      one_point_shape(cell, fe_values, dof_node, dof_component, shape);
    else
      full_rule_shape(cell, fe_values, dof_node, dof_component, n_nodes, shape);
    cell_shapes.push_back(std::move(shape));
  }
}
} // namespace vulnus::fem
