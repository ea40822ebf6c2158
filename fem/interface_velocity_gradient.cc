// The velocity gradient of the far field at its interface nodes, for a following interface
// that spreads each node's velocity field, not only its velocity, on the MPM grid: the mean
// over the node's live cells of the trilinear field's gradient at the cell's centre, turned to
// the current configuration with the cell's deformation gradient there. The far field's cells
// are boxes in the reference configuration, so the shape functions' gradients at the centre
// are (+-1 / 4 L_x, +-1 / 4 L_y, +-1 / 4 L_z).
#include "fem/far_field_data.h"

#include <deal.II/base/mpi.h>

#include <unordered_map>

namespace vulnus::fem
{
using namespace dealii;

std::vector<Tensor<2, 3>> FarFieldSolver::interface_velocity_gradients() const
{
  Data& d = *data;
  if (d.interface_cells_built_for != d.n_converted_cells)
  {
    // The live cells with an owned interface node, once per mesh.
    std::unordered_map<types::global_dof_index, int> node_of_dof;
    for (std::size_t n = 0; n < d.interface_nodes.size(); ++n)
      node_of_dof[d.interface_nodes[n].dofs[0]] = static_cast<int>(n);
    d.interface_cells.clear();
    for (const auto& cell : d.dof_handler.active_cell_iterators())
    {
      if (!(cell->is_locally_owned() || cell->is_ghost()) || d.is_converted(cell))
        continue;
      std::array<int, 8> nodes;
      bool any = false;
      for (unsigned int a = 0; a < 8; ++a)
      {
        const auto found = node_of_dof.find(cell->vertex_dof_index(a, 0));
        nodes[a] = found == node_of_dof.end() ? -1 : found->second;
        any = any || nodes[a] >= 0;
      }
      if (any)
        d.interface_cells.emplace_back(cell, nodes);
    }
    d.interface_cells_built_for = d.n_converted_cells;
  }
  // A cell on a rank boundary reads its ghost values.
  const bool distributed = Utilities::MPI::n_mpi_processes(d.comm) > 1;
  Data::Vector u_ghosted, v_ghosted;
  if (distributed)
  {
    u_ghosted.reinit(d.owned_dofs, d.relevant_dofs, d.comm);
    v_ghosted.reinit(d.owned_dofs, d.relevant_dofs, d.comm);
    u_ghosted = d.displacement;
    v_ghosted = d.velocity;
  }
  const Data::Vector& u = distributed ? u_ghosted : d.displacement;
  const Data::Vector& v = distributed ? v_ghosted : d.velocity;

  std::vector<Tensor<2, 3>> sum(d.interface_nodes.size());
  std::vector<unsigned int> count(d.interface_nodes.size(), 0);
  for (const auto& [cell, nodes] : d.interface_cells)
  {
    const Tensor<1, 3> extent = cell->vertex(7) - cell->vertex(0);
    Tensor<2, 3> F = unit_symmetric_tensor<3>(), G;
    for (unsigned int a = 0; a < 8; ++a)
    {
      Tensor<1, 3> grad_N;
      for (unsigned int c = 0; c < 3; ++c)
        grad_N[c] = (((a >> c) & 1) ? 0.25 : -0.25) / extent[c];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
        {
          F[i][j] += u(cell->vertex_dof_index(a, i)) * grad_N[j];
          G[i][j] += v(cell->vertex_dof_index(a, i)) * grad_N[j];
        }
    }
    const Tensor<2, 3> L = G * invert(F);
    for (const int n : nodes)
      if (n >= 0)
      {
        sum[n] += L;
        ++count[n];
      }
  }
  for (std::size_t n = 0; n < sum.size(); ++n)
    if (count[n] > 0)
      sum[n] /= count[n];
  return sum;
}
} // namespace vulnus::fem
