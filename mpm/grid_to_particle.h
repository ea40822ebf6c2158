// Grid-to-particle stage: point velocities (APIC, or a FLIP/PIC blend) from the nodal
// velocities, for MUSL with their momenta projected back to the nodes in the same pass; then
// the velocity gradient, the deformation gradient update (midpoint or forward Euler) and the
// position update in one gather. Rigid bodies translate with their rigid velocity.
#pragma once

#include "mpm/failure_limit_flags.h"
#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/particles.h"
#include "mpm/point_shares.h"
#include "mpm/transfer_settings.h"
#include "mpm/volume_averaging.h"

#include <vector>

namespace vulnus::mpm
{
struct KinematicsSettings
{
  double time_step = 0.0;
  double flip_fraction = 1.0; ///< 1: pure FLIP (velocity increments), 0: pure PIC
  /// Per body, overriding flip_fraction where given (empty: flip_fraction for every body).
  std::vector<double> body_flip_fraction;
  /// APIC: the deformation pass stores its velocity gradient L as C_p, the affine part of
  /// the next scatter; with flip_fraction > 0 the velocity is the FLIP-APIC blend.
  bool affine = false;
  DeformationUpdate deformation_update = DeformationUpdate::midpoint;
  /// Update each point's domain (Particles::domain) with its F; only point splitting reads it.
  bool track_domains = false;
  std::vector<char> body_is_rigid;
  std::vector<Vector3> rigid_velocity;
  /// Per body, 1 when another stepper advances its points (a subcycled projectile): they are
  /// left as they are here. Empty: none.
  std::vector<char> body_advanced_elsewhere;
  bool skips(const std::size_t b) const
  {
    return !body_advanced_elsewhere.empty() && body_advanced_elsewhere[b];
  }
};

/// Kinetic energy the grid's corrections took from the points in one velocity update (J;
/// negative where they gave some).
struct CorrectionLoss
{
  double contact = 0.0;  ///< by the contact corrections (fields.contact_change)
  double supports = 0.0; ///< by the domain faces' supports (fields.support_change)
};

/// Updates point velocities from fields.velocity (v^n) and fields.velocity_new (v^(n+1)):
/// FLIP/PIC blend. Rigid bodies take their rigid velocity. With `projection` (MUSL), the
/// same pass projects every deformable point's new momentum m v back to the nodes marked for
/// this step, into fields.projected_momentum (zero at rigid bodies' entries), using the
/// projection's per-share buffers for the contested nodes. With `book_contact`,
/// fields.contact_change holds the step's contact corrections and the function returns the
/// kinetic energy they took from these points (J; negative where they gave some): per point
/// m (|u|^2 - |u + dv_c|^2) / 2, with dv_c the weighted nodal corrections (which the FLIP and
/// the PIC velocity both carry) and u the point's mean velocity over the forces' increment,
/// (v_p + v_flip - dv_c) / 2: the correction's impulse does its work at the step's mean
/// velocity. Where contact cancels a node's force every step the step loses m |dt f / m|^2 / 2
/// that no later step gives back; this books it as the contact's (docs/validation.md).
/// With `book_supports`, fields.support_change holds the changes the face conditions made,
/// booked the same way as the supports' loss (a fixed or roller face stops nodes as contact
/// does). What is not booked is returned as 0.
CorrectionLoss update_point_kinematics(const Grid& grid, const TransferSettings& transfer,
                                       const KinematicsSettings& settings, GridFields& fields,
                                       Particles& particles, ScatterBuffers* projection,
                                       bool book_contact = false, bool book_supports = false);

/// One gather per point at its position of step n: F <- (I - dt L/2)^-1 (I + dt L/2) F
/// (midpoint) or F <- (I + dt L) F (forward Euler) with L = sum v_gradient (x) grad w, then x <- x + dt sum w v_new (v_new = fields.velocity_new, the
/// velocities of the grid update; `gradient_velocity` is the same field for USL and the
/// re-projected one for MUSL). Totally failed points (debris, whose law reads J alone) keep
/// F = J^(1/3) I with J <- J exp(dt tr L), which never inverts. With a non-null volumetric_rate (sized like the points), writes
/// ln(J_new / J_old) / dt of every point into it. Rigid bodies keep F = I and translate.
/// With `averaging`, each point's volume change is then replaced by its cell's
/// (mpm/volume_averaging.h) before the rate and the limit flags are taken.
void update_deformation_gradients_and_positions(const Grid& grid, const TransferSettings& transfer,
                                                const KinematicsSettings& settings,
                                                const GridFields& fields,
                                                const std::vector<Vector3>& gradient_velocity,
                                                Particles& particles, double* volumetric_rate,
                                                FailureLimitFlags* limit_flags = nullptr,
                                                VolumeAveraging* averaging = nullptr);
} // namespace vulnus::mpm
