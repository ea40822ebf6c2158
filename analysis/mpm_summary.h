// summary.json of an MPM run: counts, throughput, failure by type, wound metrics, bullet
// kinematics and the energy budget (every key is described in docs/reference/summary_json.md).
#pragma once

#include "analysis/momentum_audit.h"
#include "analysis/wound_sample.h"
#include "mpm/solver.h"

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace vulnus::analysis
{
struct RunTotals
{
  double wall_seconds = 0.0;
  double projectile_initial_speed = 0.0;
  double projectile_initial_kinetic_energy = 0.0;
  bool completed = true;
  std::string error; ///< blow-up message when not completed
  std::vector<std::string> warnings;
  std::uint64_t mpi_bytes_sent = 0; ///< over all ranks, by this process (a restart counts anew)
  /// Output/Wound face layer: the depth the entrance and exit wounds are measured in, m (0: one
  /// cell).
  double wound_face_layer = 0.0;
  /// Output/Wound outline grid: the face planes' grid spacing of the wound outline, m (0: none).
  double wound_outline_grid = 0.0;
};

/// Total energy accounted for (J): kinetic + strain + potential + dissipated in the materials,
/// by contact and by the supports, and carried out of the grid by removed points, less the work
/// rigid bodies of prescribed motion did on the others.
double accounted_energy(const mpm::Solver& solver, const mpm::SceneDiagnostics& d);

/// (energy - initial) / initial, 0 for a scene that starts without energy: the energy
/// balance error of history.csv, summary.json and the energy guard.
inline double relative_balance_error(const double energy, const double initial)
{
  return initial > 0 ? (energy - initial) / initial : 0.0;
}

/// The MPM scene's energy balance error: (accounted - initial) over the energy the run was
/// given, the initial energy and the work of the prescribed motions.
double mpm_balance_error(const mpm::Solver& solver, const mpm::SceneDiagnostics& d);

/// `sample`: the target's failed points and intact totals over all ranks
/// (collect_wound_sample, complete on rank 0), `d`: the diagnostics over all ranks,
/// `supports`: Solver::support_impulses (collective, so taken by the caller on every rank).
/// What became of the projectile, in words (summary "fate"): left the target through its far
/// side (the exit face of its path, `through_exit_face`), left it sideways or backwards, has
/// not reached it, stopped in it (the penetration record's stop: at most the stop speed along
/// the flight once inside), stopped and now moving backwards faster than the stop speed,
/// stopped and then left it backwards, or still moving into it. `fate` says "stopped" exactly
/// when penetration.stopped is true.
std::string projectile_fate(const mpm::ProjectileExit& exit, bool through_exit_face,
                            const mpm::ProjectilePenetration& penetration, double velocity_now,
                            double stop_speed);

/// The MPM side's momentum audit: its bodies, what left its grid, its faces' supports,
/// gravity and rigid drivers, and points added from elsewhere (the hybrid adds the far field).
MomentumAudit mpm_momentum_audit(const mpm::Solver& solver, const mpm::SceneDiagnostics& d,
                                 const std::array<mpm::Vector3, 6>& supports);

nlohmann::json mpm_summary(const mpm::Solver& solver, const RunTotals& totals,
                           const WoundSample& sample, const mpm::SceneDiagnostics& d,
                           const std::array<mpm::Vector3, 6>& supports);
} // namespace vulnus::analysis
