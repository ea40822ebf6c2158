// The checkpoints of a run directory: `checkpoints/step_NNNNNNNNNN.chk`, each written to a
// temporary name and renamed, the newest `keep` kept. A checkpoint holds the run's own
// progress (resolved deck, next output time, history length, wall time, particle and mesh output
// lists, the warnings given so far) followed by the solver's state, and ends with a tag; restart
// takes the newest one that reads completely and skips (with a warning) any that does not.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace vulnus::io
{
/// What the run loop needs besides the solver state to continue where it stopped.
struct RunProgress
{
  std::string resolved_deck;      ///< deck_used.prm of the checkpointed run
  double next_output = 0.0;       ///< simulated time of the next particle output
  std::uint64_t history_bytes = 0; ///< length of history.csv at the checkpoint
  double wall_seconds = 0.0;      ///< wall time spent up to the checkpoint
  std::string output_records;      ///< XdmfSeries::save_records of the particles
  std::string mesh_output_records; ///< XdmfSeries::save_records of the FE mesh
  std::vector<double> cavity_record; ///< analysis::TemporaryCavity::packed
  /// summary.json's warnings the steps gave so far (not those of the scene at the start, which
  /// a restart gives again), and whether the energy guard has given its one warning.
  std::vector<std::string> warnings;
  bool energy_warned = false;
};

class CheckpointStore
{
public:
  /// Checkpoints under `run_directory/folder` (created on the first write).
  explicit CheckpointStore(const std::string& run_directory, unsigned int keep = 2,
                           const std::string& folder = "checkpoints");

  /// Writes the checkpoint of `step` atomically: progress, then `write_state` fills in the
  /// solver's state. Removes older checkpoints beyond the newest `keep`. Returns the path.
  std::string write(std::uint64_t step, const RunProgress& progress,
                    const std::function<void(std::ostream&)>& write_state) const;

  /// Reads the newest checkpoint that is complete: its progress is returned and
  /// `read_state` is given the stream positioned at the solver's state (it must throw
  /// std::runtime_error if the state is unusable, then the next older one is tried).
  /// `warn` receives one line per skipped checkpoint; `path` the one used. Throws
  /// std::runtime_error when there is none.
  RunProgress read_newest(const std::function<void(std::istream&)>& read_state,
                          const std::function<void(const std::string&)>& warn,
                          std::string& path) const;

  /// The resolved deck in the newest checkpoint whose header can be read ("" when none): what
  /// a restart compares with its own deck before it restores any state.
  std::string newest_deck() const;

  /// Checkpoint files, newest first (temporary files excluded).
  std::vector<std::string> files() const;

  const std::string& directory() const { return folder; }

private:
  std::string folder;
  unsigned int keep;
};
} // namespace vulnus::io
