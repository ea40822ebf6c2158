// The far field's failed tissue as material points for the wound figures: each live cell whose
// Gauss points carry a failure flag gives the points a conversion would make of it, on the
// MPM lattice, each with the flag of the Gauss point in its octant.
#include "fem/far_field_data.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace vulnus::fem
{
using namespace dealii;

std::vector<FailedLatticePoint> FarFieldSolver::failed_lattice_points(const double spacing) const
{
  const Data& d = *data;
  AssertThrow(spacing > 0.0, ExcMessage("failed_lattice_points needs a positive spacing"));
  AssertThrow(d.prm.degree == 1 && (d.n_q_points == 8 || d.n_q_points == 1),
              ExcMessage("failed lattice points from a far field need linear elements"));
  std::vector<FailedLatticePoint> points;
  for (const auto& cell : d.dof_handler.active_cell_iterators())
  {
    if (!d.owns_live(cell))
      continue;
    const std::size_t first = std::size_t(cell->active_cell_index()) * d.n_q_points;
    const auto states = d.committed_states.begin() + static_cast<std::ptrdiff_t>(first);
    if (std::all_of(states, states + d.n_q_points,
                    [](const materials::PointState& s) { return s.failure == 0; }))
      continue;
    const unsigned int per_axis = static_cast<unsigned int>(
      std::max(1L, std::lround(cell->extent_in_direction(0) / spacing)));
    const QIterated<3> lattice(QMidpoint<1>(), per_axis);
    FEValues<3> fe_values(d.mapping, d.fe, lattice, update_JxW_values | update_quadrature_points);
    fe_values.reinit(cell);
    for (unsigned int q = 0; q < lattice.size(); ++q)
    {
      // The Gauss point of the same octant (2 x 2 x 2 Gauss, x fastest), or the one point.
      const Point<3>& xi = lattice.point(q);
      const unsigned int gauss =
        d.n_q_points == 1 ? 0 : (xi[0] > 0.5) + 2 * (xi[1] > 0.5) + 4 * (xi[2] > 0.5);
      const std::uint8_t failure = states[gauss].failure;
      if (failure != 0)
        points.push_back({fe_values.quadrature_point(q), fe_values.JxW(q), failure,
                          d.cell_stress[cell->active_cell_index()]});
    }
  }
  return points;
}
} // namespace vulnus::fem
