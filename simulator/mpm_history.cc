// Rows of the MPM time history.
#include "simulator/mpm_history.h"

#include "analysis/mpm_summary.h"
#include "mpm/symmetry_planes.h"

#include <cmath>

namespace vulnus::simulator
{
std::vector<std::string> mpm_history_columns()
{
  return {"time_s", "dt_s", "step", "kinetic_J", "strain_J", "potential_J", "dissipated_material_J",
          "dissipated_contact_J", "dissipated_supports_J", "outflow_J", "energy_balance_error",
          "momentum_x", "momentum_y", "momentum_z", "intact", "failed_matrix", "failed_fiber",
          "failed_total", "bullet_position_x", "bullet_position_y", "bullet_position_z",
          "bullet_velocity_x", "bullet_velocity_y", "bullet_velocity_z", "bullet_contact_force_x",
          "bullet_contact_force_y", "bullet_contact_force_z", "contact_nodes", "active_nodes",
          "points", "target_kinetic_J", "target_momentum_x", "target_momentum_y",
          "target_momentum_z", "support_impulse_x-", "support_impulse_x+", "support_impulse_y-",
          "support_impulse_y+", "support_impulse_z-", "support_impulse_z+"};
}

std::vector<double> mpm_history_row(const mpm::Solver& solver, const mpm::SceneDiagnostics& d)
{
  const double balance = analysis::mpm_balance_error(solver, d);
  mpm::Vector3 position = mpm::Vector3::Constant(NAN), velocity = position, force = position;
  if (solver.projectile() >= 0)
  {
    const mpm::BodySummary& b = d.bodies[solver.projectile()];
    // A mirror plane through the projectile models part of it; the whole one's centre is on
    // the plane.
    std::vector<mpm::SymmetryPlane> through;
    for (const mpm::SymmetryPlane& plane : solver.mirror_planes())
      if (mpm::crosses(solver.scene().bodies[solver.projectile()], plane))
        through.push_back(plane);
    position = mpm::onto_planes(b.centroid, through);
    velocity = b.velocity;
    force = solver.contact_forces().empty() ? mpm::Vector3::Zero()
                                            : solver.contact_forces()[solver.projectile()];
  }
  double target_kinetic = 0.0;
  mpm::Vector3 target_momentum = mpm::Vector3::Zero();
  for (std::size_t b = 0; b < d.bodies.size(); ++b)
    if (static_cast<int>(b) != solver.projectile())
    {
      target_kinetic += d.bodies[b].kinetic_energy;
      target_momentum += d.bodies[b].mass * d.bodies[b].velocity;
    }
  // Each face's impulse along its own normal axis (N s).
  const std::array<mpm::Vector3, 6> supports = solver.support_impulses(); // collective
  return {solver.time(),
          solver.last_time_step(),
          double(solver.step_count()),
          d.kinetic_energy,
          d.strain_energy,
          d.potential_energy,
          d.dissipated_energy,
          solver.contact_dissipation(),
          solver.support_dissipation(),
          solver.removed_energy(),
          balance,
          d.momentum[0],
          d.momentum[1],
          d.momentum[2],
          double(d.failure_counts[0]),
          double(d.failure_counts[1]),
          double(d.failure_counts[2]),
          double(d.failure_counts[3]),
          position[0],
          position[1],
          position[2],
          velocity[0],
          velocity[1],
          velocity[2],
          force[0],
          force[1],
          force[2],
          double(solver.contact_nodes()),
          double(solver.active_nodes_all_ranks()),
          double(solver.n_points_all_ranks()),
          target_kinetic,
          target_momentum[0],
          target_momentum[1],
          target_momentum[2],
          supports[0][0],
          supports[1][0],
          supports[2][1],
          supports[3][1],
          supports[4][2],
          supports[5][2]};
}
} // namespace vulnus::simulator
