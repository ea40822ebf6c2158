// The coarsest far-field cell touching each slab face: the supports' reactions there are only
// as resolved as those cells (docs/far_field.md section 2, "Coarse cells at a support").
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
          const BoundingBox<3> box = cell->bounding_box();
          double largest = 0.0;
          for (unsigned int c = 0; c < 3; ++c)
            largest = std::max(largest, box.side_length(c));
          double& face = coarsest[cell->face(f)->boundary_id()];
          face = std::max(face, largest);
        }
  for (double& face : coarsest)
    face = Utilities::MPI::max(face, d.comm);
  return coarsest;
}
} // namespace vulnus::fem
