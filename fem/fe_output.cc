// The far field's mesh for output: each rank packs its live owned cells (corner positions,
// displacement and velocity at the corners, cell stress, failure, rank), rank 0 gathers them
// and merges the corners that several cells share into one vertex.
#include "fem/far_field_data.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace vulnus::fem
{
using namespace dealii;

namespace
{
// Per cell: 8 corners x (reference position, displacement, velocity), then 6 stress
// components, the failure flag and the rank.
constexpr unsigned int corner_values = 9;
constexpr unsigned int values_per_cell = 8 * corner_values + 6 + 2;
// deal.II numbers a hexahedron's corners lexicographically (x fastest); XDMF and VTK go
// round the bottom face, then round the top face.
constexpr unsigned int dealii_corner_of_xdmf[8] = {0, 1, 3, 2, 4, 5, 7, 6};

std::vector<double> pack_owned_cells(const FarFieldSolver::Data& d)
{
  FarFieldSolver::Data::Vector u(d.ghosted), v(d.ghosted);
  u = d.displacement;
  v = d.velocity;
  const unsigned int rank = Utilities::MPI::this_mpi_process(d.comm);
  std::vector<double> packed;
  packed.reserve(d.triangulation.n_active_cells() * values_per_cell /
                 Utilities::MPI::n_mpi_processes(d.comm));
  for (const auto& cell : d.dof_handler.active_cell_iterators())
  {
    if (!d.owns_live(cell))
      continue;
    for (const unsigned int corner : dealii_corner_of_xdmf)
    {
      const Point<3>& x = cell->vertex(corner);
      packed.insert(packed.end(), {x[0], x[1], x[2]});
      for (const FarFieldSolver::Data::Vector* field : {&u, &v})
        for (unsigned int c = 0; c < 3; ++c)
          packed.push_back((*field)[cell->vertex_dof_index(corner, c)]);
    }
    const unsigned int k = cell->active_cell_index();
    const Tensor<2, 3>& s = d.cell_stress[k];
    packed.insert(packed.end(), {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]});
    packed.push_back(d.cell_failure[k]);
    packed.push_back(rank);
  }
  return packed;
}
} // namespace

FeMeshForOutput FarFieldSolver::mesh_for_output() const
{
  const Data& d = *data;
  const std::vector<std::vector<double>> all_cells =
      Utilities::MPI::gather(d.comm, pack_owned_cells(d), 0);
  FeMeshForOutput mesh;
  if (Utilities::MPI::this_mpi_process(d.comm) != 0)
    return mesh;

  // Corners shared by cells (also across ranks) sit at the same reference position; they are
  // matched on it, rounded to 1e-10 of the mesh's extent (far below any cell size).
  double extent = 0.0;
  for (const std::vector<double>& cells : all_cells)
    for (std::size_t i = 0; i < cells.size(); i += values_per_cell)
      for (unsigned int corner = 0; corner < 8; ++corner)
        for (unsigned int c = 0; c < 3; ++c)
          extent = std::max(extent, std::abs(cells[i + corner_values * corner + c]));
  const double tolerance = 1e-10 * std::max(extent, 1e-3);
  std::map<std::array<long long, 3>, std::int32_t> vertex_at;
  for (const std::vector<double>& cells : all_cells)
    for (std::size_t first = 0; first + values_per_cell <= cells.size(); first += values_per_cell)
    {
      const double* cell = cells.data() + first;
      for (unsigned int corner = 0; corner < 8; ++corner)
      {
        const double* values = cell + corner_values * corner;
        const std::array<long long, 3> key = {std::llround(values[0] / tolerance),
                                              std::llround(values[1] / tolerance),
                                              std::llround(values[2] / tolerance)};
        const auto [place, is_new] =
            vertex_at.emplace(key, static_cast<std::int32_t>(mesh.positions.size() / 3));
        if (is_new)
          for (unsigned int c = 0; c < 3; ++c)
          {
            mesh.positions.push_back(values[c] + values[3 + c]);
            mesh.displacement.push_back(values[3 + c]);
            mesh.velocity.push_back(values[6 + c]);
          }
        mesh.hexahedra.push_back(place->second);
      }
      const double* rest = cell + 8 * corner_values;
      mesh.stress.insert(mesh.stress.end(), rest, rest + 6);
      mesh.failure.push_back(static_cast<std::uint8_t>(rest[6]));
      mesh.rank.push_back(static_cast<std::uint32_t>(rest[7]));
    }
  return mesh;
}
} // namespace vulnus::fem
