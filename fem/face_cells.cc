// The widest far-field cell across each slab face: a support's reaction is only as resolved as
// the cells' widths along its normal (docs/far_field.md section 2, "Cells at a support").
#include "fem/far_field_data.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>

#include <algorithm>

namespace vulnus::fem
{
using namespace dealii;

std::array<double, n_slab_faces> FarFieldSolver::coarsest_cells_on_faces() const
{
  const Data& d = *data;
  std::array<double, n_slab_faces> coarsest{};
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (d.owns_live(cell))
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() < n_slab_faces)
        {
          const types::boundary_id id = cell->face(f)->boundary_id();
          const double across = cell->bounding_box().side_length(id / 2);
          coarsest[id] = std::max(coarsest[id], across);
        }
  for (double& face : coarsest)
    face = Utilities::MPI::max(face, d.comm);
  return coarsest;
}
} // namespace vulnus::fem
