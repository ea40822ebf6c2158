// The solver's side of a free rigid projectile's neglected rotation (mpm/neglected_rotation.h),
// and the mass distribution it and the rigid hold start from.
#include "mpm/solver.h"

#include <algorithm>

namespace vulnus::mpm
{
Solver::MassDistribution Solver::mass_distribution(const std::size_t b) const
{
  // First and second moments over all ranks.
  std::vector<double> moments(13, 0.0); // m, m x (3), m x x^T (9)
  for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
  {
    const double m = particles.mass[p];
    const Vector3& x = particles.position[p];
    moments[0] += m;
    for (int i = 0; i < 3; ++i)
    {
      moments[1 + i] += m * x[i];
      for (int j = 0; j < 3; ++j)
        moments[4 + 3 * i + j] += m * x[i] * x[j];
    }
  }
  ranks.sum(moments.data(), static_cast<int>(moments.size()));
  MassDistribution d;
  d.mass = moments[0];
  if (!(d.mass > 0.0))
    return d;
  d.centre = Vector3(moments[1], moments[2], moments[3]) / d.mass;
  Eigen::Matrix3d second;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      second(i, j) = moments[4 + 3 * i + j] - d.mass * d.centre[i] * d.centre[j];
  d.inertia = second.trace() * Eigen::Matrix3d::Identity() - second;
  for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
    d.radius = std::max(d.radius, (particles.position[p] - d.centre).norm());
  d.radius = ranks.max(d.radius);
  return d;
}

void Solver::begin_rotation_estimate()
{
  // A sphere turned about its centre occupies the same place: its path and wound are the
  // same whether it turns or not (only a frictional contact's slip would differ).
  const int b = projectile_body;
  if (b < 0 || !materials_of_body[b]->is_rigid() ||
      parameters.bodies[b].rigid_motion != RigidMotion::free || !contact_active ||
      parameters.bodies[b].shape == BodyShape::sphere)
    return;
  const MassDistribution d = mass_distribution(static_cast<std::size_t>(b));
  if (d.mass > 0.0)
    rotation_estimate.begin(d.centre, d.inertia, d.radius, parameters.cell_size);
}

void Solver::estimate_projectile_rotation(const double dt)
{
  if (!rotation_estimate.active())
    return;
  const auto b = static_cast<std::size_t>(projectile_body);
  rotation_estimate.add(grid_result.contact_force[b], grid_result.contact_moment[b],
                        grid_settings.rigid_velocity[b], dt, static_cast<long>(n_steps + 1),
                        current_time + dt);
}
} // namespace vulnus::mpm
