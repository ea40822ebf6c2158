// A deformable projectile held rigid while it stays far below yield (Time/Rigid projectile
// while elastic): it translates as a rigid body, with no stress update and no substeps, as
// long as two checks hold, and turns deformable for the rest of the run at the first step
// either fails.
//   - Contact pressure: the largest contact force on one of its nodes over the node's area
//     h^2, averaged over the time the projectile takes to cross a cell, stays below a fraction
//     of its yield stress (over at most 100 steps, so that a slow projectile's steady load
//     counts whole). A grid contact gives a node layer its momentum in one step, so the
//     force of a single step grows as the step shrinks; over one cell's crossing it is the
//     continuum's (rho v^2 where a crushable target is swept up).
//   - Rotation: the contact's moment about the mass centre would turn it so little that its
//     farthest point moves less than a tenth of a cell (the held body only translates).
// Before the run, the acoustic impact pressure v Zp Zt / (Zp + Zt) against the stiffest
// target body decides whether it is held at all.
#pragma once

#include "mpm/particles.h"

#include <Eigen/Core>

#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace vulnus::mpm
{
struct RigidHoldLimits
{
  double yield_stress = 0.0;    ///< Pa, the projectile law's elastic limit
  double stress_fraction = 0.5; ///< of the yield stress, limit of the contact pressure
  double cell_size = 0.0;       ///< m; a node's area is its square
  double drift_cells = 0.1;     ///< limit of the neglected rotation's travel, in cells
};

/// What the hold did, for the log and summary.json.
struct RigidHoldRecord
{
  bool applies = false;          ///< the scene asked for it and the projectile qualifies
  bool held = false;             ///< held rigid now
  double impact_pressure = 0.0;  ///< Pa, acoustic estimate before the run
  double peak_pressure = 0.0;    ///< Pa, largest averaged contact pressure while held
  double peak_pressure_time = 0.0;
  double rotation_drift = 0.0;   ///< m, travel of the farthest point by the neglected rotation
  long release_step = -1;        ///< step at whose end it turned deformable, or -1
  double release_time = 0.0;
  std::string reason;            ///< why it is not held (from the start, or since release)
  /// The scene asked for the hold and the projectile was held, or declined with a reason.
  bool considered() const { return applies || !reason.empty(); }
};

class RigidHold
{
public:
  RigidHold() = default;
  /// Decides before the run. `impact_pressure`: the acoustic estimate; `centre`, `inertia`
  /// (about the centre) and `radius` (farthest point from it): the projectile's mass
  /// distribution. Returns whether it is held.
  bool begin(const RigidHoldLimits& limits, double impact_pressure, const Vector3& centre,
             const Eigen::Matrix3d& inertia, double radius);
  /// Not held, for a reason outside the checks (the scene's contact cannot hold it).
  void decline(const std::string& why);
  /// After a held step's contact: the step's largest nodal contact force on the projectile,
  /// the contact's total force and moment about x = 0, the velocity it moved with over the
  /// step dt, and the step's end (step number and time). Returns false, once, when a check
  /// fails: it is then released, and the caller makes it deformable.
  bool check(double peak_node_force, const Vector3& force, const Vector3& moment_about_origin,
             const Vector3& velocity, double dt, long step, double time);
  /// Releases it for a reason outside the checks (e.g. a velocity field given to its points).
  void release(const std::string& why, long step, double time);
  const RigidHoldRecord& record() const { return state; }
  double pressure_limit() const { return limits.stress_fraction * limits.yield_stress; }
  double drift_limit() const { return limits.drift_cells * limits.cell_size; }

  /// The evolving state as numbers and back (checkpoints; the reason travels as text).
  std::vector<double> packed() const;
  void unpack(const std::vector<double>& values, const std::string& reason);

private:
  static constexpr double window_steps = 100.0;
  RigidHoldLimits limits;
  RigidHoldRecord state;
  Vector3 centre = Vector3::Zero();
  Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Zero();
  double radius = 0.0;
  Vector3 angular_momentum = Vector3::Zero(); ///< the contact's angular impulse about the centre
  double rotation_angle = 0.0;                ///< integral of |omega| dt
  std::deque<std::pair<double, double>> window; ///< (dt, peak nodal force) of recent steps
};
} // namespace vulnus::mpm
