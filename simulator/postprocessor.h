// What the time loop calls around the steps: each postprocessor owns one kind of record
// (history, particle series, mesh series) and writes it for every run type that has it.
// A checkpoint stores how far each had got (io::RunProgress), a restart resumes from there.
#pragma once

#include "io/checkpoint_store.h"
#include "simulator/stepper.h"

#include <string>

namespace vulnus::simulator
{
class Postprocessor
{
public:
  virtual ~Postprocessor() = default;

  /// A fresh run: the record of the initial state.
  virtual void start(Stepper& stepper) = 0;
  /// A restarted run: continue from the checkpoint's progress.
  virtual void resume(Stepper& stepper, const io::RunProgress& progress) = 0;
  /// After every step: the records due.
  virtual void after_step(Stepper& stepper) = 0;
  /// The run reached its end: the final record.
  virtual void finish(Stepper& stepper) = 0;
  /// Everything recorded so far on disk (before a checkpoint, at a stop or blow-up).
  virtual void flush() {}
  /// How far this postprocessor has got, into the checkpoint's progress.
  virtual void save_progress(io::RunProgress& progress) const = 0;
  /// What it adds to summary.json (rank 0 writes it; its records are complete there).
  virtual void add_to_summary(nlohmann::json& /*summary*/) const {}
  /// Where the last state it wrote can be found ("" when it keeps none).
  virtual std::string last_state() const { return {}; }
};
} // namespace vulnus::simulator
