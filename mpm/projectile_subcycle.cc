// The projectile's substeps: the scene's stages run over its points alone, with the contact
// force lent to the points as an external load.
#include "mpm/projectile_subcycle.h"

#include "mpm/particle_to_grid.h"
#include "mpm/stencil.h"

#include <algorithm>
#include <cmath>

namespace vulnus::mpm
{
ProjectileSubcycle::ProjectileSubcycle(const Grid& scene_grid, const SubcycleStages& settings)
  : grid(scene_grid), stages(settings)
{
  grid.clear_active_nodes(); // the scene's nodes, none of them active for this body yet
  // One body on its own grid: no contact, and no ownership test (every rank of a distributed
  // run advances the whole body; the scene's test would look its keys up in the scene's grid).
  stages.grid_update.contact = false;
  stages.grid_update.owns_node = nullptr;
  stages.kinematics.body_flip_fraction.clear();
  stages.kinematics.body_advanced_elsewhere.clear();
  stages.stress.body_advanced_elsewhere.clear();
}

std::vector<Vector3> contact_force_on_points(const Grid& grid, const TransferSettings& transfer,
                                             const GridFields& fields,
                                             const std::vector<Vector3>& trial,
                                             const Particles& particles, const std::size_t b,
                                             const double dt)
{
  const long begin = particles.begin_of(b), end = particles.end_of(b);
  const std::size_t n_bodies = fields.n_bodies;
  const double lp = transfer.half_size_cells[b];
  std::vector<Vector3> force(end - begin, Vector3::Zero());
  with_shape(transfer.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
#pragma omp parallel for schedule(static)
               for (long p = begin; p < end; ++p)
               {
                 Vector3 change = Vector3::Zero();
                 for_each_node<shape>(grid, lp, particles.position[p], particles.deformation_gradient[p],
                                      [&](const std::int64_t key, const double w, const Vector3&)
                                      {
                                        const std::int32_t slot = grid.slot(key);
                                        change += w * (fields.velocity_new[slot * n_bodies + b] -
                                                       trial[slot]);
                                      });
                 force[p - begin] = (particles.mass[p] / dt) * change;
               }
             });
  return force;
}

SubcycleResult ProjectileSubcycle::advance(Particles& points, const std::vector<Vector3>& point_force,
                                           const double dt, const int n_substeps,
                                           const double flip_fraction)
{
  SubcycleResult result;
  const double h = dt / n_substeps;
  stages.grid_update.time_step = h;
  stages.kinematics.time_step = h;
  stages.kinematics.flip_fraction =
    flip_fraction > 0.0 ? std::pow(flip_fraction, 1.0 / n_substeps) : 0.0;
  stages.stress.time_step = h;
  double* rate = nullptr;
  if (stages.stress.uses_viscosity())
  {
    volumetric_rate.resize(points.size());
    rate = volumetric_rate.data();
  }
  GridUpdateResult grid_result;
  StressUpdateResult stress_result;
  velocity_before.resize(points.size());
  for (int k = 0; k < n_substeps; ++k)
  {
    std::copy(points.velocity.begin(), points.velocity.end(), velocity_before.begin());
    mark_active_nodes(points, stages.transfer, grid);
    particles_to_grid(points, grid, stages.transfer, buffers, fields, point_force.data());
    update_grid(grid, stages.grid_update, fields, grid_result);
    for (int f = 0; f < 6; ++f)
      result.support_impulse[f] += grid_result.support_impulse[f];
    const CorrectionLoss loss =
      update_point_kinematics(grid, stages.transfer, stages.kinematics, fields, points,
                              stages.musl ? &buffers : nullptr, false,
                              any_support(stages.grid_update.faces));
    result.support_loss += loss.supports;
    if (stages.musl)
      velocities_from_momenta(grid, stages.grid_update, fields);
    update_deformation_gradients_and_positions(
      grid, stages.transfer, stages.kinematics, fields,
      stages.musl ? fields.velocity : fields.velocity_new, points, rate);
    double work = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : work)
    for (long p = 0; p < static_cast<long>(points.size()); ++p)
      work += 0.5 * h * point_force[p].dot(velocity_before[p] + points.velocity[p]);
    result.contact_work += work;
    update_stresses(stages.stress, rate, points, stress_result);
    result.max_von_mises_over_yield =
      std::max(result.max_von_mises_over_yield, stress_result.max_von_mises_over_yield[0]);
    if (stress_result.failed_point >= 0)
    {
      result.failed_point = stress_result.failed_point;
      result.failure_message = "in substep " + std::to_string(k + 1) + " of " +
                               std::to_string(n_substeps) + ": " + stress_result.failure_message;
      break;
    }
  }
  return result;
}
} // namespace vulnus::mpm
