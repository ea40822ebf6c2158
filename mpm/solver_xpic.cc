// The solver's XPIC(m) and FMPM(m) step: the series' correction on the grid (from v^n or from
// v^(n+1)), summed over ranks after each pass over the points (mpm/xpic.h).
#include "mpm/solver.h"
#include "mpm/axisymmetry.h"
#include "mpm/xpic.h"

namespace vulnus::mpm
{
void Solver::compute_xpic_correction()
{
  // The MUSL projection's buffers are free until the points' update: each pass uses them.
  fields.xpic_correction.assign(fields.velocity.size(), Vector3::Zero());
  const bool full_mass = parameters.velocity_transfer == VelocityTransfer::fmpm;
  first_xpic_term(grid, grid_settings, fields, full_mass ? fields.velocity_new : fields.velocity,
                  xpic_term);
  for (int k = 1; k < parameters.series_order; ++k)
  {
    scatter_point_values(grid, transfer, kinematics, particles, xpic_term,
                         fields.projected_momentum, buffers.momentum_per_share);
    sum_projected_momenta_with_neighbours();
    std::array<Vector3, 6> stopped;
    stopped.fill(Vector3::Zero());
    next_xpic_term(grid, grid_settings, fields, fields.projected_momentum, xpic_term,
                   fields.xpic_correction, stopped);
    for (int f = 0; f < 6; ++f)
      support_impulse_here[f] += parameters.axisymmetric ? revolved(stopped[f]) : stopped[f];
  }
}
} // namespace vulnus::mpm
