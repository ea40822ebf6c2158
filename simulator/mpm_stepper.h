// The pure-MPM stepper: one mpm::Solver over all bodies, on one process or in slabs over
// the ranks of a communicator. Writes checkpoints.
#pragma once

#include "deck/run_parameters.h"
#include "mpm/solver.h"
#include "simulator/stepper.h"

namespace vulnus::simulator
{
/// What summary.json reports about the projectile against its initial state.
struct ProjectileStart
{
  double speed = 0.0;          ///< m/s along the flight direction
  double kinetic_energy = 0.0; ///< J
};

/// The projectile's initial speed and kinetic energy (zeros without a projectile). Collective.
ProjectileStart projectile_start(const mpm::Solver& solver);

/// The MPM-side warnings of a finished run: a projectile far below yield, an exact rigid
/// surface it did not keep, a rigid projectile that would have turned, points removed.
std::vector<std::string> mpm_final_warnings(const mpm::Solver& solver);

/// elastic_projectile_note for a finished run ("\n" + note, or empty).
std::string projectile_note(const mpm::Solver& solver);

/// The closing line's bullet part, from summary.json's "bullet": its exit velocity, or that it
/// has not left the target.
std::string bullet_report(const nlohmann::json& summary);
/// "; wound figures not resolved at this cell: ..." from summary.json's wound_resolution, or "".
std::string unresolved_wound_report(const nlohmann::json& summary);
/// "\npenetration depth not resolved at this cell: ..." when the projectile stopped in the
/// target and summary.json's penetration.resolution says its depth is not resolved, or "".
std::string unresolved_penetration_report(const nlohmann::json& summary);

/// "time step .., particle-to-grid .., ..., checks .." (s): where an MPM solver's time went.
std::string phase_report(const mpm::PhaseTimes& times);

/// A closing note when a deformable projectile stayed elastic (peak von Mises below 0.1 of its
/// yield stress) while its own substeps took more than half of the run: the rigid model would
/// spare them. Empty otherwise.
std::string elastic_projectile_note(double substep_seconds, double run_seconds,
                                    double peak_von_mises_over_yield,
                                    const std::string& projectile_material);

class MpmStepper : public Stepper
{
public:
  MpmStepper(const deck::RunParameters& parameters, MPI_Comm communicator);

  const char* method() const override { return "MPM"; }
  void log_scene(io::RunDirectory& directory) const override;
  void advance() override { solver.advance(); }
  bool finished() const override { return solver.finished(); }
  double time() const override { return solver.time(); }
  double end_time() const override { return solver.scene().end_time; }
  double expected_end_time() const override { return solver.expected_end_time(); }
  std::uint64_t step_count() const override { return solver.step_count(); }
  double last_time_step() const override { return solver.last_time_step(); }
  std::string progress() const override;
  MPI_Comm communicator() const override { return solver.rank_group().communicator(); }
  std::string blow_up_remedy() const override;
  double energy_balance_error() const override;
  std::string energy_error_causes() const override;

  std::vector<std::string> history_columns() const override;
  std::vector<double> history_row() const override;
  std::vector<std::string> events() override;
  std::vector<std::string> final_warnings() const override;
  nlohmann::json summary(const analysis::RunTotals& totals) const override;
  std::string final_report(const nlohmann::json& summary) const override;

  const mpm::Solver* mpm_side() const override { return &solver; }

  bool can_checkpoint() const override { return true; }
  void save(std::ostream& out) const override { solver.save(out); }
  void restore(std::istream& in) override
  {
    solver.restore(in);
    hold_release_reported = solver.projectile_hold().record().release_step >= 0;
    rotation_reported = solver.projectile_rotation().exceeded_step() >= 0;
  }

private:
  mpm::Solver solver;
  std::size_t n_points_at_start;
  ProjectileStart projectile; ///< from the initial state, before any restart
  bool hold_release_reported = false;
  bool rotation_reported = false;
};
} // namespace vulnus::simulator
