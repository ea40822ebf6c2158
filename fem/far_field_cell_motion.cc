// The far field's cells that move unlike a finite element can follow: interface cells whose
// nodes leave their best-fit affine motion (fem/cell_motion.h), and cells distorted beyond a
// stretch or corner-Jacobian bound. Waves and rigid motion are affine over a cell and flag
// nothing; the adaptive zone converts the cells these return.
#include "fem/cell_motion.h"
#include "fem/far_field_data.h"
#include "fem/mesh_builder.h"

#include <deal.II/base/mpi.h>

namespace vulnus::fem
{
using namespace dealii;

std::vector<FlaggedCell> FarFieldSolver::cells_moving_unlike_elements(const CellMotionLimits& limits) const
{
  const Data& d = *data;
  Data::Vector u(d.owned_dofs, d.relevant_dofs, d.comm);
  u = d.displacement;
  std::vector<double> mine; // x, y, z, cause per flagged cell
  for (const auto& cell : d.dof_handler.active_cell_iterators())
  {
    if (!d.owns_live(cell))
      continue;
    bool on_interface = false;
    for (const unsigned int f : cell->face_indices())
      on_interface = on_interface ||
                     (cell->face(f)->at_boundary() ? cell->face(f)->boundary_id() == boundary_ids::interface
                                                   : d.is_converted(cell->neighbor(f)));
    const bool wanted = limits.deviatoric_stretch > 0.0 || limits.jacobian_ratio > 0.0 ||
                        (on_interface && limits.non_affine > 0.0);
    if (!wanted)
      continue;
    CellNodes X, displacement;
    for (unsigned int a = 0; a < 8; ++a)
    {
      for (unsigned int c = 0; c < 3; ++c)
      {
        X[a][c] = cell->vertex(a)[c];
        displacement[a][c] = u(cell->vertex_dof_index(a, c));
      }
    }
    const CellMotion m = cell_motion(X, displacement, d.cell_size[cell->active_cell_index()]);
    CellMotionCause cause = CellMotionCause::none;
    if ((limits.deviatoric_stretch > 0.0 && m.deviatoric_stretch > limits.deviatoric_stretch) ||
        (limits.jacobian_ratio > 0.0 && m.jacobian_ratio < limits.jacobian_ratio))
      cause = CellMotionCause::distortion;
    else if (on_interface && limits.non_affine > 0.0 && m.non_affine > limits.non_affine)
      cause = CellMotionCause::non_affine_motion;
    if (cause == CellMotionCause::none)
      continue;
    const Point<3> centre = cell->center();
    mine.insert(mine.end(), {centre[0], centre[1], centre[2], static_cast<double>(cause)});
  }
  std::vector<FlaggedCell> flagged;
  for (const std::vector<double>& theirs : Utilities::MPI::all_gather(d.comm, mine))
    for (std::size_t i = 0; i + 3 < theirs.size(); i += 4)
      flagged.push_back({Point<3>(theirs[i], theirs[i + 1], theirs[i + 2]),
                         static_cast<CellMotionCause>(static_cast<int>(theirs[i + 3]))});
  return flagged;
}
} // namespace vulnus::fem
