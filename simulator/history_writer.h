// The CSV time history (history.csv) of every run type: a row of the stepper's columns at
// the start, every `history_interval` steps and at the end (unless that step has its row).
// At the end it reads the supports' impulses back for their late mean and range.
#pragma once

#include "io/csv_history.h"
#include "io/run_directory.h"
#include "simulator/postprocessor.h"

#include <cstdint>
#include <memory>

namespace vulnus::simulator
{
class HistoryWriter : public Postprocessor
{
public:
  /// Every rank builds one (the rows are collective); rank 0 writes.
  HistoryWriter(io::RunDirectory& directory, unsigned int history_interval);

  void start(Stepper& stepper) override;
  void resume(Stepper& stepper, const io::RunProgress& progress) override;
  void after_step(Stepper& stepper) override;
  void finish(Stepper& stepper) override;
  void flush() override;
  void save_progress(io::RunProgress& progress) const override;
  /// Into each face of summary["supports"] that history.csv has a support_impulse column
  /// for: the mean and range of that (normal) impulse over the second half of the run
  /// (analysis/late_window.h), phase-independent figures of a ringing reaction.
  void add_to_summary(nlohmann::json& summary) const override;

private:
  void add_row(const Stepper& stepper);

  io::RunDirectory& directory;
  unsigned int interval;
  std::uint64_t last_row_step = std::uint64_t(-1); ///< step of the newest row of this process
  std::unique_ptr<io::CsvHistory> history;         ///< rank 0 only
};
} // namespace vulnus::simulator
