// The solver's side of contact with a rigid body's exact surface (Contact/Rigid surface =
// exact, mpm/shape_distance.h): which bodies take one, and where their shapes are each step.
#include "mpm/solver.h"

#include "mpm/body_builder.h"

namespace vulnus::mpm
{
void Solver::plan_exact_rigid_surfaces()
{
  const std::size_t n_bodies = parameters.bodies.size();
  grid_settings.exact_surface.assign(n_bodies, nullptr);
  grid_settings.rigid_offset.assign(n_bodies, Vector3::Zero());
  grid_settings.point_half_spacing.assign(n_bodies, 0.0);
  if (!parameters.contact.exact_rigid_surface)
    return;
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    const BodyParameters& body = parameters.bodies[b];
    grid_settings.point_half_spacing[b] = transfer.half_size_cells[b] * parameters.cell_size;
    const bool may_be_rigid = grid_settings.body_is_rigid[b] ||
                              (parameters.rigid_projectile_while_elastic &&
                               static_cast<int>(b) == projectile_body);
    if (may_be_rigid)
      grid_settings.exact_surface[b] = &body;
    if (materials_of_body[b]->is_rigid() && body_mass[b] > 0.0)
    {
      // The body is its shape: its mass too, shared by its points in their proportions.
      const double exact_mass =
        body.density * body_volume(body) * modelled_share(body, planes_of_symmetry);
      const double scale = exact_mass / body_mass[b];
      for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
        particles.mass[p] *= scale;
      body_mass[b] = exact_mass;
    }
  }
}

void Solver::update_rigid_surfaces()
{
  if (!parameters.contact.exact_rigid_surface)
    return;
  const std::size_t n_bodies = particles.n_bodies();
  std::vector<double> sums(4 * n_bodies, 0.0); // displacement (3), count
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    if (!grid_settings.exact_surface[b] || !grid_settings.body_is_rigid[b])
      continue;
    for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
    {
      const Vector3 displacement =
        particles.position[p] - particles.reference_position[p].cast<double>();
      for (int d = 0; d < 3; ++d)
        sums[4 * b + d] += displacement[d];
      sums[4 * b + 3] += 1.0;
    }
  }
  ranks.sum(sums.data(), static_cast<int>(sums.size()));
  for (std::size_t b = 0; b < n_bodies; ++b)
    if (sums[4 * b + 3] > 0.0)
      grid_settings.rigid_offset[b] =
        Vector3(sums[4 * b], sums[4 * b + 1], sums[4 * b + 2]) / sums[4 * b + 3];
}
} // namespace vulnus::mpm
