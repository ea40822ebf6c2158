// The solver's step results of an axisymmetric scene, revolved about the axis.
#include "mpm/solver.h"

#include "mpm/axisymmetry.h"

namespace vulnus::mpm
{
void Solver::revolve_step_results()
{
  for (Vector3& force : grid_result.contact_force)
    force = revolved(force);
  // A ring's moment about the axis cancels over the ring.
  for (Vector3& moment : grid_result.contact_moment)
    moment.setZero();
  for (Vector3& impulse : grid_result.support_impulse)
    impulse = revolved(impulse);
}
} // namespace vulnus::mpm
