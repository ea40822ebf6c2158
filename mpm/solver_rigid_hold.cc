// The solver's side of a projectile held rigid while elastic (mpm/rigid_hold.h): the decision
// before the run, the checks after each step's contact, and the release.
#include "mpm/solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vulnus::mpm
{
std::vector<double> Solver::body_impedances() const
{
  std::vector<double> impedance(particles.n_bodies(), 0.0);
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
    if (!grid_settings.body_is_rigid[b])
      for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
        impedance[b] = std::max(impedance[b], parameters.bodies[b].density * particles.wave_speed[p]);
  ranks.max(impedance.data(), static_cast<int>(impedance.size()));
  return impedance;
}

void Solver::begin_rigid_hold()
{
  const int b = projectile_body;
  if (!parameters.rigid_projectile_while_elastic || b < 0 || grid_settings.body_is_rigid[b] ||
      particles.n_bodies() < 2 || !contact_active)
    return;
  if (grid_settings.correct_projected_velocities)
  {
    rigid_hold.decline("Contact/Passes = two corrects the projected velocities, of which a "
                       "rigid body takes no share");
    return;
  }

  // The acoustic pressure of a flat impact on the stiffest other body (infinite impedance
  // for a rigid one).
  const std::vector<double> impedance = body_impedances();
  double target = 0.0;
  for (std::size_t other = 0; other < particles.n_bodies(); ++other)
    if (static_cast<int>(other) != b)
      target = std::max(target, grid_settings.body_is_rigid[other]
                                  ? std::numeric_limits<double>::infinity()
                                  : impedance[other]);
  const double speed = parameters.bodies[b].initial_velocity.norm();
  const double own = impedance[b];
  const double impact = std::isinf(target) ? own * speed : speed * own * target / (own + target);

  // The mass distribution about the mass centre (solver_rigid_rotation.cc).
  const MassDistribution distribution = mass_distribution(static_cast<std::size_t>(b));
  const double mass = distribution.mass;
  if (!(mass > 0.0))
    return;

  RigidHoldLimits limits;
  limits.yield_stress = materials_of_body[b]->elastic_limit_stress();
  limits.stress_fraction = parameters.rigid_projectile_stress_limit;
  limits.cell_size = parameters.cell_size;
  if (!rigid_hold.begin(limits, impact, distribution.centre, distribution.inertia,
                        distribution.radius))
    return;

  // Rigid with its mean velocity, which is its points' own when they share one (as a body
  // whose law is rigid would move, to the bit); no stress update.
  Vector3 momentum = Vector3::Zero();
  double spread = 0.0;
  for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
  {
    momentum += particles.mass[p] * particles.velocity[p];
    spread = std::max(spread, (particles.velocity[p] - parameters.bodies[b].initial_velocity).norm());
  }
  ranks.sum(momentum.data(), 3);
  spread = ranks.max(spread);
  grid_settings.body_is_rigid[b] = 1;
  grid_settings.rigid_velocity[b] =
    spread == 0.0 ? parameters.bodies[b].initial_velocity : Vector3(momentum / mass);
  kinematics.body_is_rigid = grid_settings.body_is_rigid;
  kinematics.rigid_velocity = grid_settings.rigid_velocity;
  stress_settings.body_advanced_elsewhere.assign(particles.n_bodies(), 0);
  stress_settings.body_advanced_elsewhere[b] = 1;
}

bool Solver::check_rigid_hold(const double dt, const Vector3& velocity_over_step)
{
  const auto b = static_cast<std::size_t>(projectile_body);
  return !rigid_hold.check(grid_result.peak_node_force[b], grid_result.contact_force[b],
                           grid_result.contact_moment[b], velocity_over_step, dt,
                           static_cast<long>(n_steps + 1), current_time + dt);
}

void Solver::make_projectile_deformable()
{
  const auto b = static_cast<std::size_t>(projectile_body);
  if (!grid_settings.body_is_rigid[b])
    return;
  // Its points keep the held velocity and F = I: an unstressed body from here on.
  grid_settings.body_is_rigid[b] = 0;
  kinematics.body_is_rigid[b] = 0;
  stress_settings.body_advanced_elsewhere[b] = 0;
  plan_projectile_subcycle();
}
} // namespace vulnus::mpm
