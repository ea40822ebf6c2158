// Grid-to-particle stage: point velocities (FLIP/PIC blend) and displacements from the nodal
// velocities, then the velocity gradient and the deformation gradient update
// F <- (I + dt L) F. Rigid bodies translate with their rigid velocity.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/particles.h"
#include "mpm/transfer_settings.h"

#include <vector>

namespace vulnus::mpm
{
struct KinematicsSettings
{
  double time_step = 0.0;
  double flip_fraction = 1.0; ///< 1: pure FLIP (velocity increments), 0: pure PIC
  std::vector<char> body_is_rigid;
  std::vector<Vector3> rigid_velocity;
};

/// Updates point velocities from fields.velocity and fields.velocity_new and writes each
/// point's displacement of this step (dt times the interpolated v_new) into displacement;
/// positions move later (move_points), after the velocity gradient used the same stencil.
void update_point_kinematics(const Grid& grid, const TransferSettings& transfer,
                             const KinematicsSettings& settings, const GridFields& fields,
                             Particles& particles, std::vector<Vector3>& displacement);

/// x <- x + displacement.
void move_points(const std::vector<Vector3>& displacement, Particles& particles);

/// F <- (I + dt L) F with L = sum v_new (x) grad w; writes the volumetric strain rate
/// ln(J_new / J_old) / dt of every point into volumetric_rate. Rigid bodies keep F = I.
void update_deformation_gradients(const Grid& grid, const TransferSettings& transfer,
                                  const KinematicsSettings& settings, const GridFields& fields,
                                  Particles& particles, std::vector<double>& volumetric_rate);
} // namespace vulnus::mpm
