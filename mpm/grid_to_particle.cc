// Gather from the grid to the points: velocities (with the MUSL momentum projection in the
// same pass), then deformation gradients and positions.
#include "mpm/grid_to_particle.h"

#include "mpm/deformation_update.h"
#include "mpm/stencil.h"
#include "mpm/volume_averaging.h"

#include <array>
#include <cmath>

namespace vulnus::mpm
{
namespace
{
/// Velocity update of the points of one share of one deformable body: the FLIP/PIC blend
/// v = a (v_p + sum w (v_i^(n+1) - v_i^n)) + (1 - a) sum w v_i^(n+1), XPIC's correction
/// (`xpic`, when not null) added to the PIC part. With Project (MUSL),
/// each point's new momentum goes back to the nodes it read from, with the same weights. With
/// Book, returns the kinetic energy the contact corrections (`contact`, when not null) and the
/// supports (`supports`, when not null) took from the points (see update_point_kinematics).
template <ShapeFunction shape, bool project, bool book>
CorrectionLoss update_share_velocities(const Grid& grid, const double lp, const double flip,
                                       const std::size_t b, const ShareRange range,
                                       const GridFields& fields, Particles& particles,
                                       Vector3* momentum, Vector3* contested,
                                       const Vector3* contact, const Vector3* supports,
                                       const Vector3* xpic)
{
  constexpr int n_entries = stencil_entries(shape);
  const std::size_t n_bodies = particles.n_bodies();
  CorrectionLoss loss;
  for (long p = range.begin; p < range.end; ++p)
  {
    Vector3 v_pic = Vector3::Zero();
    Vector3 dv = Vector3::Zero();
    Vector3 dv_contact = Vector3::Zero();
    Vector3 dv_supports = Vector3::Zero();
    std::array<std::int32_t, n_entries> slots;
    std::array<double, n_entries> weights;
    int n_nodes = 0;
    for_each_node<shape>(grid, lp, particles.position[p], particles.deformation_gradient[p],
                         [&](const std::int64_t key, const double w, const Vector3&)
                         {
                           const std::int32_t slot = grid.slot(key);
                           const std::size_t e = slot * n_bodies + b;
                           v_pic += w * fields.velocity_new[e];
                           if (xpic)
                             v_pic += w * xpic[e];
                           dv += w * (fields.velocity_new[e] - fields.velocity[e]);
                           if constexpr (book)
                           {
                             if (contact)
                               dv_contact += w * contact[e];
                             if (supports)
                               dv_supports += w * supports[e];
                           }
                           if constexpr (project)
                           {
                             slots[n_nodes] = slot;
                             weights[n_nodes++] = w;
                           }
                         });
    const Vector3 v_flip = particles.velocity[p] + dv;
    const Vector3 v = flip * v_flip + (1.0 - flip) * v_pic;
    // m (|u|^2 - |u + dv_c|^2) / 2 with u = (v_p + v_flip - dv_c) / 2, without the difference
    // of squares; the supports' change likewise.
    if constexpr (book)
    {
      const Vector3 twice_mean = particles.velocity[p] + v_flip;
      loss.contact -= 0.5 * particles.mass[p] * dv_contact.dot(twice_mean);
      loss.supports -= 0.5 * particles.mass[p] * dv_supports.dot(twice_mean);
    }
    // Kinetic energy the blend takes from the FLIP velocity (PIC's damping), booked as
    // dissipated so the energy balance closes.
    if (flip < 1.0)
      particles.dissipated_density[p] += 0.5 * particles.mass[p] *
                                         (v_flip.squaredNorm() - v.squaredNorm()) /
                                         particles.reference_volume[p];
    particles.velocity[p] = v;
    if constexpr (project)
    {
      const Vector3 mv = particles.mass[p] * v;
      for (int i = 0; i < n_nodes; ++i)
        scatter_target(grid, slots[i], n_bodies, b, momentum, contested) += weights[i] * mv;
    }
  }
  return loss;
}
/// ln(J_new / J_old) / dt, or `fallback` (the trace of L) where either J is not positive.
double volume_rate(const double J_old, const double J_new, const double dt, const double fallback)
{
  return (J_new > 0.0 && J_old > 0.0) ? std::log(J_new / J_old) / dt : fallback;
}
} // namespace

CorrectionLoss update_point_kinematics(const Grid& grid, const TransferSettings& transfer,
                                       const KinematicsSettings& s, GridFields& fields,
                                       Particles& particles, ScatterBuffers* projection,
                                       const bool book_contact, const bool book_supports)
{
  const std::size_t n_bodies = particles.n_bodies();
  const bool book = book_contact || book_supports;
  const Vector3* contact = book_contact ? fields.contact_change.data() : nullptr;
  const Vector3* supports = book_supports ? fields.support_change.data() : nullptr;
  const Vector3* xpic = fields.xpic_correction.empty() ? nullptr : fields.xpic_correction.data();
  // Per share and body, summed in that order afterwards: the same total on every run.
  std::vector<CorrectionLoss> losses(book ? grid.n_point_shares() * n_bodies : 0);
  with_shape(
      transfer.shape,
      [&](auto shape_constant)
      {
        constexpr ShapeFunction shape = decltype(shape_constant)::value;
        // One share's points of body b; momentum and contested are null without projection.
        auto update = [&](const int share, const std::size_t b, const ShareRange range,
                          Vector3* momentum, Vector3* contested)
        {
          const double flip =
            s.body_flip_fraction.empty() ? s.flip_fraction : s.body_flip_fraction[b];
          const double lp = transfer.half_size_cells[b];
          if (s.skips(b))
            return;
          if (s.body_is_rigid[b])
            for (long p = range.begin; p < range.end; ++p)
              particles.velocity[p] = s.rigid_velocity[b];
          else if (book)
            losses[share * n_bodies + b] =
              momentum ? update_share_velocities<shape, true, true>(
                           grid, lp, flip, b, range, fields, particles, momentum, contested,
                           contact, supports, xpic)
                       : update_share_velocities<shape, false, true>(
                           grid, lp, flip, b, range, fields, particles, nullptr, nullptr,
                           contact, supports, xpic);
          else if (momentum)
            update_share_velocities<shape, true, false>(grid, lp, flip, b, range, fields,
                                                        particles, momentum, contested,
                                                        nullptr, nullptr, xpic);
          else
            update_share_velocities<shape, false, false>(grid, lp, flip, b, range, fields,
                                                         particles, nullptr, nullptr,
                                                         nullptr, nullptr, xpic);
        };
        if (projection)
        {
          fields.projected_momentum.resize(grid.n_active() * n_bodies);
          scatter_by_shares(grid, particles, Vector3::Zero().eval(), fields.projected_momentum,
                            projection->momentum_per_share, update);
        }
        else
          visit_shares_in_parallel(particles, grid.n_point_shares(),
                                   [&](const int share, const std::size_t b,
                                       const ShareRange range)
                                   { update(share, b, range, nullptr, nullptr); });
      });
  CorrectionLoss total;
  for (const CorrectionLoss& loss : losses)
  {
    total.contact += loss.contact;
    total.supports += loss.supports;
  }
  return total;
}

void update_deformation_gradients_and_positions(const Grid& grid, const TransferSettings& transfer,
                                                const KinematicsSettings& s,
                                                const GridFields& fields,
                                                const std::vector<Vector3>& gradient_velocity,
                                                Particles& particles, double* volumetric_rate,
                                                FailureLimitFlags* limit_flags,
                                                VolumeAveraging* averaging)
{
  const std::size_t n_bodies = particles.n_bodies();
  const double dt = s.time_step;
  const bool midpoint = s.deformation_update == DeformationUpdate::midpoint;
  const bool affine = s.affine;
  const bool track_domains = s.track_domains;
  const bool axisymmetric = grid.axisymmetric();
  if (averaging)
    averaging->prepare(grid, particles.size());
  with_shape(transfer.shape,
             [&](auto shape_constant)
             {
               constexpr ShapeFunction shape = decltype(shape_constant)::value;
               for (std::size_t b = 0; b < n_bodies; ++b)
               {
                 const long begin = particles.begin_of(b), end = particles.end_of(b);
                 if (s.skips(b))
                   continue;
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
                 const materials::FailureParameters* criterion =
                     limit_flags ? limit_flags->criterion[b] : nullptr;
                 const bool fibers = criterion && limit_flags->fibers[b];
                 std::uint8_t* passed = criterion ? limit_flags->passed.data() : nullptr;
                 if (criterion)
                   limit_flags->filled[b] = 1;
                 const double lp = transfer.half_size_cells[b];
                 // Named here: clang 14 rejects the outer function's parameters inside an OpenMP
                 // loop nested in two lambdas.
                 const std::vector<Vector3>& velocity_new = fields.velocity_new;
                 const std::vector<Vector3>& velocity_for_gradient = gradient_velocity;
#pragma omp parallel for schedule(static)
                 for (long p = begin; p < end; ++p)
                 {
                   Tensor2& F = particles.deformation_gradient[p];
                   const Vector3 x_start = particles.position[p];
                   Tensor2 L = Tensor2::Zero();
                   Vector3 v = Vector3::Zero();
                   double radial_velocity = 0.0;
                   const Vector3 start_in_cells = for_each_node<shape>(
                       grid, lp, particles.position[p], F,
                       [&](const std::int64_t key, const double w, const Vector3& grad_w)
                       {
                         const std::size_t e = grid.slot(key) * n_bodies + b;
                         L.noalias() += velocity_for_gradient[e] * grad_w.transpose();
                         v += w * velocity_new[e];
                         radial_velocity += w * velocity_for_gradient[e][0];
                       });
                   particles.position[p] += dt * v;
                   // APIC's affine velocity is this L: for MUSL from the re-projected
                   // velocities, mass-weighted means of point velocities, so a light node's
                   // v + dt f / m never reaches the scatter through it. Its hoop rate is left
                   // out: the nodes across the hoop direction are one ring.
                   if (affine)
                     particles.affine_velocity[p] = L.cast<float>();
                   if (axisymmetric)
                     L(2, 2) = radial_velocity / x_start[0];
                   if (track_domains)
                   {
                     const Tensor2 domain = particles.domain[p].cast<double>();
                     particles.domain[p] =
                       (midpoint ? midpoint_update((0.5 * dt) * L, domain)
                                 : Tensor2((Tensor2::Identity() + dt * L) * domain))
                         .cast<float>();
                   }
                   const bool failed = particles.failure[p] != 0;
                   const bool debris = particles.failure[p] == materials::total_failure;
                   const double J_old =
                     (volumetric_rate || averaging || failed) ? F.determinant() : 0.0;
                   if (averaging)
                   {
                     averaging->j_old[p] = J_old;
                     averaging->cell[p] = debris ? -1 : VolumeAveraging::cell_key_at(grid, start_in_cells);
                   }
                   if (!debris && midpoint)
                   {
                     F = midpoint_update((0.5 * dt) * L, F);
                   }
                   else if (!debris)
                     F = (Tensor2::Identity() + dt * L) * F;
                   if (debris || (failed && !(F.determinant() > 0.0)))
                   {
                     // Debris keeps only its volume (its law reads J alone); the exponential
                     // volume update never inverts it, whatever fragments cross its nodes. A
                     // failed point this step would invert (nothing resists it under Stress
                     // after failure = zero) is crushed to debris.
                     F = std::cbrt(J_old * std::exp(dt * L.trace())) * Tensor2::Identity();
                     particles.failure[p] = materials::total_failure;
                   }
                   if (averaging)
                   {
                     // Rate and limits once the cell has its mean volume change; L's trace
                     // is the rate's fallback.
                     if (volumetric_rate)
                       volumetric_rate[p] = L.trace();
                     continue;
                   }
                   if (volumetric_rate)
                     volumetric_rate[p] = volume_rate(J_old, F.determinant(), dt, L.trace());
                   if (criterion)
                     passed[p] = limits_passed(*criterion, fibers, F, particles.fiber_direction[p]);
                 }
                 if (!averaging)
                   continue;
                 if (averaging->from_grid_flux)
                   impose_grid_flux_volume_changes(
                       grid, {velocity_for_gradient, fields.data, n_bodies, b, dt, midpoint},
                       begin, end, particles, *averaging);
                 else
                   average_volume_changes(begin, end, particles, *averaging);
                 if (!volumetric_rate && !criterion)
                   continue;
#pragma omp parallel for schedule(static)
                 for (long p = begin; p < end; ++p)
                 {
                   const Tensor2& F = particles.deformation_gradient[p];
                   if (volumetric_rate)
                     volumetric_rate[p] = volume_rate(averaging->j_old[p], F.determinant(), dt,
                                                      volumetric_rate[p]);
                   if (criterion)
                     passed[p] = limits_passed(*criterion, fibers, F, particles.fiber_direction[p]);
                 }
               }
             });
}
} // namespace vulnus::mpm
