// The interface the one time loop (simulator.h) drives: a scene that advances step by step
// and says what the postprocessors record. Three steppers implement it: pure MPM
// (mpm_stepper.h), hybrid MPM-FE (hybrid_stepper.h) and pure FE (fe_stepper.h).
#pragma once

#include "analysis/mpm_summary.h"

#include <mpi.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace vulnus::mpm
{
class Solver;
}
namespace vulnus::fem
{
class FarFieldSolver;
}
namespace vulnus::io
{
class RunDirectory;
}

namespace vulnus::simulator
{
class Stepper
{
public:
  virtual ~Stepper() = default;

  /// summary.json's "method": "MPM", "hybrid" or "FE".
  virtual const char* method() const = 0;
  /// Collective: the scene's description, logged at the start.
  virtual void log_scene(io::RunDirectory& directory) const = 0;

  /// One step. Throws mpm::BlowUp, std::runtime_error or dealii::ExceptionBase.
  virtual void advance() = 0;
  virtual bool finished() const = 0;
  virtual double time() const = 0;
  virtual double end_time() const = 0;
  /// Collective: when the run will most likely end (the progress line's time left).
  virtual double expected_end_time() const { return end_time(); }
  virtual std::uint64_t step_count() const = 0;
  virtual double last_time_step() const = 0;
  /// What a progress line adds after time, step and dt.
  virtual std::string progress() const = 0;
  /// The ranks the stepper runs on (MPI_COMM_NULL for a serial pure-MPM run).
  virtual MPI_Comm communicator() const = 0;
  /// The deck entries a blow-up most likely asks to change.
  virtual std::string blow_up_remedy() const = 0;
  /// Collective: the energy neither present, dissipated nor removed, over the scene's
  /// reference energy (summary.json's energy.balance_error, now).
  virtual double energy_balance_error() const = 0;
  /// What most likely breaks the energy balance of this kind of run.
  virtual std::string energy_error_causes() const = 0;
  /// Collective, after every step and at the end (`final_check`): the scene's own validity
  /// monitors. Returns the warnings to record now; throws mpm::BlowUp for one that stops the
  /// run.
  virtual std::vector<std::string> check_validity(bool /*final_check*/) { return {}; }
  /// What the last step changed in the scene itself, one log line each (the adaptive zone's
  /// growth); rank 0 logs them.
  virtual std::vector<std::string> events() { return {}; }

  virtual std::vector<std::string> history_columns() const = 0;
  /// Collective: one row matching history_columns().
  virtual std::vector<double> history_row() const = 0;

  /// Collective: what the finished run should warn about.
  virtual std::vector<std::string> final_warnings() const = 0;
  /// Collective: summary.json without "warnings" (complete on rank 0, empty elsewhere).
  virtual nlohmann::json summary(const analysis::RunTotals& totals) const = 0;
  /// The closing line of the log, from the summary (rank 0).
  virtual std::string final_report(const nlohmann::json& summary) const = 0;

  /// The particles, for the particle output and the wound; null without an MPM side.
  virtual const mpm::Solver* mpm_side() const { return nullptr; }
  /// The far field, for the mesh output; null without an FE side.
  virtual fem::FarFieldSolver* fe_side() { return nullptr; }
  /// The body index of the far field's material among the scene's bodies (the mesh output's
  /// material_id, which the particles share).
  virtual std::int32_t fe_material_id() const { return 0; }

  /// Checkpoints: a stepper that cannot save its state is stopped without one.
  virtual bool can_checkpoint() const { return false; }
  virtual void save(std::ostream& out) const;
  virtual void restore(std::istream& in);
};
} // namespace vulnus::simulator
