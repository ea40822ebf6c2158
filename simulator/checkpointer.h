// Checkpoints of a run and the restart from them: the stepper's state plus how far every
// postprocessor had got, written every N steps, every N s of wall time and on a stop signal;
// a restart checks that the deck still matches before anything continues.
#pragma once

#include "deck/run_parameters.h"
#include "io/checkpoint_store.h"
#include "io/run_directory.h"
#include "mpm/rank_group.h"
#include "simulator/postprocessor.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace vulnus::simulator
{
/// A restart whose deck differs from the checkpoint's in an entry a restart may not change:
/// an input error (exit status 2), not a failure of the run.
class RestartRefused : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

class Checkpointer
{
public:
  /// Every rank builds one; each rank of a distributed run keeps its own checkpoints.
  Checkpointer(const deck::RunParameters& parameters, io::RunDirectory& directory,
               const mpm::RankGroup& ranks);

  /// Restores the stepper and resumes every postprocessor from the newest complete
  /// checkpoint; returns its progress (the warnings the run had given). Throws
  /// std::runtime_error when there is none or the ranks disagree, and RestartRefused when the
  /// deck differs from the checkpoint's in an entry a restart may not change.
  io::RunProgress restart(Stepper& stepper,
                          const std::vector<std::unique_ptr<Postprocessor>>& postprocessors);

  /// True when the step or wall-clock interval of checkpoints has passed.
  bool due(const Stepper& stepper, double run_wall_seconds) const;

  /// Writes a checkpoint now (the postprocessors flushed first), with the warnings the steps
  /// gave so far and whether the energy guard gave its own; returns its path.
  std::string write(const Stepper& stepper,
                    const std::vector<std::unique_ptr<Postprocessor>>& postprocessors,
                    const std::vector<std::string>& warnings, bool energy_warned,
                    double run_wall_seconds);

  /// Wall time spent by the earlier processes of a restarted run (0 for a fresh run).
  double earlier_wall_seconds() const { return wall_before_restart; }

  /// The newest checkpoint and how to continue from it ("" when there is none).
  std::string last_state() const;

  void log_policy() const;

private:
  const deck::RunParameters& parameters;
  io::RunDirectory& directory;
  const mpm::RankGroup& ranks;
  io::CheckpointStore store;
  double wall_before_restart = 0.0;
  double wall_at_last_checkpoint = 0.0;
  std::string newest;
  std::uint64_t newest_step = 0;
};
} // namespace vulnus::simulator
