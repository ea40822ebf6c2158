// What a pure-MPM run writes while it runs, and how it continues after a restart: the CSV
// history, the particle output series and the checkpoints, kept consistent with each other
// (a checkpoint records how far the history and the series had got).
#pragma once

#include "app/checkpoint_store.h"
#include "app/csv_history.h"
#include "app/particle_output.h"
#include "app/run_directory.h"
#include "app/run_parameters.h"
#include "mpm/solver.h"

#include <memory>
#include <string>

namespace vulnus::app
{
class MpmRunFiles
{
public:
  /// Every rank of a distributed run builds one; the calls below are collective then.
  MpmRunFiles(const RunParameters& parameters, RunDirectory& directory, const mpm::RankGroup& ranks);

  /// A fresh run: the first particle output and history row. With `Output.restart`: the
  /// solver, history and output series continue from the newest complete checkpoint (throws
  /// std::runtime_error when there is none or it belongs to another deck).
  void start(mpm::Solver& solver);

  /// The history row and particle output due after a step.
  void after_step(const mpm::Solver& solver);

  /// Final history row and particle output; flushes the history.
  void finish(const mpm::Solver& solver);

  /// True when the step or wall-clock interval of checkpoints has passed.
  bool checkpoint_due(const mpm::Solver& solver, double run_wall_seconds) const;

  /// Writes a checkpoint now; `run_wall_seconds` is this process's wall time so far.
  std::string write_checkpoint(const mpm::Solver& solver, double run_wall_seconds);

  /// Wall time spent by the earlier processes of a restarted run (0 for a fresh run).
  double earlier_wall_seconds() const { return wall_before_restart; }

  /// Where the last good state is: the newest checkpoint or the last particle output.
  std::string last_good_state() const;

  const ParticleOutput& particle_output() const { return output; }

private:
  void restart(mpm::Solver& solver);
  void add_history_row(const mpm::Solver& solver);

  const RunParameters& parameters;
  RunDirectory& directory;
  const mpm::RankGroup& ranks;
  ParticleOutput output;
  CheckpointStore checkpoints;
  std::unique_ptr<CsvHistory> history; ///< rank 0 only
  double next_output = 0.0;
  double wall_before_restart = 0.0;
  double wall_at_last_checkpoint = 0.0;
  std::string newest_checkpoint;
  std::size_t newest_checkpoint_step = 0;
};
} // namespace vulnus::app
