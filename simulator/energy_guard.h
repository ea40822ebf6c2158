// The energy guard every run keeps: the scene's energy balance error is checked every few
// steps; past the warning bound the run says so once, with the step and the likely causes,
// and past the limit it stops as a blow-up.
#pragma once

#include "deck/run_parameters.h"
#include "simulator/stepper.h"

#include <optional>
#include <string>

namespace vulnus::simulator
{
class EnergyGuard
{
public:
  /// Steps between checks (and none before the first of them: the first steps of a driven
  /// scene measure their error against a reference energy still being built up).
  static constexpr std::uint64_t check_interval = 10;

  explicit EnergyGuard(const deck::EnergyGuardParameters& bounds) : bounds(bounds) {}

  /// Collective on a check step (or with `final_check`): the warning to record, once, when
  /// the error first passes the warning bound. Throws mpm::BlowUp past the limit.
  std::optional<std::string> check(const Stepper& stepper, bool final_check = false);

  /// Whether it has given its warning, for checkpoints: a restarted run does not give it again
  /// at a later crossing.
  bool has_warned() const { return warned; }
  void restore(const bool has_warned) { warned = has_warned; }

private:
  deck::EnergyGuardParameters bounds;
  bool warned = false;
};
} // namespace vulnus::simulator
