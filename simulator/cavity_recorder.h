// The temporary cavity's record (analysis/temporary_cavity.h) of every run with an MPM side
// and a projectile: sampled every few steps, kept across checkpoints, written into
// summary.json's "temporary_cavity".
#pragma once

#include "analysis/temporary_cavity.h"
#include "simulator/postprocessor.h"

#include <cstdint>

namespace vulnus::simulator
{
class CavityRecorder : public Postprocessor
{
public:
  /// Collective (every rank builds one); samples every `interval` steps and at the end.
  explicit CavityRecorder(unsigned int interval = 5) : interval(interval) {}

  void start(Stepper& stepper) override;
  void resume(Stepper& stepper, const io::RunProgress& progress) override;
  void after_step(Stepper& stepper) override;
  void finish(Stepper& stepper) override;
  void save_progress(io::RunProgress& progress) const override;
  void add_to_summary(nlohmann::json& summary) const override;

private:
  unsigned int interval;
  analysis::TemporaryCavity cavity;
};
} // namespace vulnus::simulator
