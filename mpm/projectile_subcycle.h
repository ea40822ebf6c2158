// Subcycling of a stiff deformable projectile (Time/Subcycle projectile): the scene steps at
// the target's CFL step, and inside it the projectile's points advance alone in n substeps
// of their own CFL step. The scene's step resolves contact once, with every body on the grid;
// the contact force it found at the projectile's nodes is lent to the projectile's points
// by their mass shares (f_p = m_p / dt sum_i w_ip dv_i), so the substeps deliver the whole
// impulse whatever nodes the points reach meanwhile.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/grid_to_particle.h"
#include "mpm/grid_update.h"
#include "mpm/particles.h"
#include "mpm/point_shares.h"
#include "mpm/stress_update.h"
#include "mpm/transfer_settings.h"

#include <array>
#include <string>
#include <vector>

namespace vulnus::mpm
{
/// The stages' settings for the projectile's points alone (a one-body scene: no contact).
struct SubcycleStages
{
  TransferSettings transfer;
  GridUpdateSettings grid_update;
  KinematicsSettings kinematics;
  StressUpdateSettings stress;
  bool musl = true;
};

struct SubcycleResult
{
  double max_von_mises_over_yield = 0.0;
  /// A point whose material update failed, as an index into the body, or -1; its message.
  long failed_point = -1;
  std::string failure_message;
  /// Work the lent contact force did on the points over the substeps (J).
  double contact_work = 0.0;
  /// Kinetic energy the domain faces' supports took from the points over the substeps (J).
  double support_loss = 0.0;
  /// Impulse the domain faces gave the points over the substeps, by face (N s).
  std::array<Vector3, 6> support_impulse = {Vector3::Zero(), Vector3::Zero(), Vector3::Zero(),
                                            Vector3::Zero(), Vector3::Zero(), Vector3::Zero()};
};

/// The contact force over the scene's step dt on each point of body b (one per point, in the
/// body's order), from the body's nodal velocities before (`trial`, per active node) and after
/// the contact correction in `fields`: f_p = m_p / dt sum_i w_ip (v_i - trial_i).
std::vector<Vector3> contact_force_on_points(const Grid& grid, const TransferSettings& transfer,
                                             const GridFields& fields,
                                             const std::vector<Vector3>& trial,
                                             const Particles& particles, std::size_t b, double dt);

class ProjectileSubcycle
{
public:
  /// `grid`: the scene's grid, whose geometry the substeps use.
  ProjectileSubcycle(const Grid& grid, const SubcycleStages& stages);

  /// Advances the one-body container `projectile` by n_substeps steps of dt / n_substeps,
  /// loaded by `point_force` (per point, held over the step) and gravity. `flip_fraction`: the
  /// scene's FLIP fraction for a step dt (each substep takes its n-th root, so that the
  /// relaxation rate stays fixed in time).
  SubcycleResult advance(Particles& projectile, const std::vector<Vector3>& point_force, double dt,
                         int n_substeps, double flip_fraction);

private:
  Grid grid;
  SubcycleStages stages;
  GridFields fields;
  ScatterBuffers buffers;
  std::vector<double> volumetric_rate;
  std::vector<Vector3> velocity_before; ///< per point, at the start of a substep
};
} // namespace vulnus::mpm
