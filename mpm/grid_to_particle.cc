// Gather from the grid to the points: kinematics and deformation gradients.
#include "mpm/grid_to_particle.h"

#include "mpm/stencil.h"

#include <cmath>

namespace vulnus::mpm
{
void update_point_kinematics(const Grid& grid, const TransferSettings& transfer,
                             const KinematicsSettings& s, const GridFields& fields,
                             Particles& particles)
{
  const std::size_t n_bodies = particles.n_bodies();
  const double flip = s.flip_fraction;
  with_shape(transfer.shape, [&](auto shape_constant) {
    constexpr ShapeFunction shape = decltype(shape_constant)::value;
    for (std::size_t b = 0; b < n_bodies; ++b)
    {
      const long begin = particles.begin_of(b), end = particles.end_of(b);
      if (s.body_is_rigid[b])
      {
        const Vector3 v = s.rigid_velocity[b];
#pragma omp parallel for schedule(static)
        for (long p = begin; p < end; ++p)
          particles.velocity[p] = v;
        continue;
      }
      const double lp = transfer.half_size_cells[b];
      // Named here: clang 14 rejects the outer function's parameters inside an OpenMP loop
      // nested in two lambdas.
      const std::vector<Vector3>& velocity_new = fields.velocity_new;
      const std::vector<Vector3>& velocity_old = fields.velocity;
#pragma omp parallel for schedule(static)
      for (long p = begin; p < end; ++p)
      {
        Vector3 v_pic = Vector3::Zero();
        Vector3 dv = Vector3::Zero();
        for_each_node<shape>(grid, lp, particles.position[p],
                             [&](const std::int64_t key, const double w, const Vector3&) {
                               const std::size_t e = grid.slot(key) * n_bodies + b;
                               v_pic += w * velocity_new[e];
                               dv += w * (velocity_new[e] - velocity_old[e]);
                             });
        particles.velocity[p] = flip * (particles.velocity[p] + dv) + (1.0 - flip) * v_pic;
      }
    }
  });
}

void update_deformation_gradients_and_positions(const Grid& grid, const TransferSettings& transfer,
                                                const KinematicsSettings& s,
                                                const GridFields& fields,
                                                const std::vector<Vector3>& gradient_velocity,
                                                Particles& particles, double* volumetric_rate)
{
  const std::size_t n_bodies = particles.n_bodies();
  const double dt = s.time_step;
  with_shape(transfer.shape, [&](auto shape_constant) {
    constexpr ShapeFunction shape = decltype(shape_constant)::value;
    for (std::size_t b = 0; b < n_bodies; ++b)
    {
      const long begin = particles.begin_of(b), end = particles.end_of(b);
      if (s.body_is_rigid[b])
      {
        const Vector3 step = dt * s.rigid_velocity[b];
#pragma omp parallel for schedule(static)
        for (long p = begin; p < end; ++p)
        {
          particles.position[p] += step;
          if (volumetric_rate)
            volumetric_rate[p] = 0.0;
        }
        continue;
      }
      const double lp = transfer.half_size_cells[b];
      // Named here: clang 14 rejects the outer function's parameters inside an OpenMP loop
      // nested in two lambdas.
      const std::vector<Vector3>& velocity_new = fields.velocity_new;
      const std::vector<Vector3>& velocity_for_gradient = gradient_velocity;
#pragma omp parallel for schedule(static)
      for (long p = begin; p < end; ++p)
      {
        Tensor2 L = Tensor2::Zero();
        Vector3 v = Vector3::Zero();
        for_each_node<shape>(grid, lp, particles.position[p],
                             [&](const std::int64_t key, const double w, const Vector3& grad_w) {
                               const std::size_t e = grid.slot(key) * n_bodies + b;
                               L.noalias() += velocity_for_gradient[e] * grad_w.transpose();
                               v += w * velocity_new[e];
                             });
        particles.position[p] += dt * v;
        Tensor2& F = particles.deformation_gradient[p];
        const double J_old = volumetric_rate ? F.determinant() : 0.0;
        F = (Tensor2::Identity() + dt * L) * F;
        if (volumetric_rate)
        {
          const double J_new = F.determinant();
          volumetric_rate[p] =
            (J_new > 0.0 && J_old > 0.0) ? std::log(J_new / J_old) / dt : L.trace();
        }
      }
    }
  });
}
} // namespace vulnus::mpm
