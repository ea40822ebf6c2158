// The energy guard: bounds on the energy balance error, with the likely causes named.
#include "simulator/energy_guard.h"

#include "mpm/solver.h"

#include <cmath>
#include <sstream>

namespace vulnus::simulator
{
namespace
{
/// The error and its likely causes; with the step and time unless a failure report adds them.
std::string describe(const Stepper& stepper, const double error, const bool with_step)
{
  std::ostringstream o;
  o << "energy balance error " << error;
  if (with_step)
    o << " at step " << stepper.step_count() << " (t = " << stepper.time() << " s)";
  o << ": "
    << (error > 0 ? "the scene gained energy that nothing supplied"
                  : "the scene lost energy that no dissipation accounts for")
    << "; likely causes: " << stepper.energy_error_causes();
  return o.str();
}
} // namespace

std::optional<std::string> EnergyGuard::check(const Stepper& stepper, const bool final_check)
{
  if (!final_check && (stepper.step_count() == 0 || stepper.step_count() % check_interval != 0))
    return std::nullopt;
  if (bounds.warning <= 0.0 && bounds.limit <= 0.0)
    return std::nullopt;
  const double error = stepper.energy_balance_error(); // collective
  if (bounds.limit > 0.0 && std::abs(error) > bounds.limit)
  {
    std::ostringstream o;
    o << describe(stepper, error, false) << "; it passed Time/Energy balance limit = "
      << bounds.limit << ", so the run's answer cannot be trusted";
    throw mpm::BlowUp(o.str());
  }
  if (warned || bounds.warning <= 0.0 || !(std::abs(error) > bounds.warning))
    return std::nullopt;
  warned = true;
  std::ostringstream o;
  o << describe(stepper, error, true) << " (beyond Time/Energy balance warning = " << bounds.warning
    << "; checked every " << check_interval << " steps)";
  return o.str();
}
} // namespace vulnus::simulator
