// Validity monitors of a hybrid run (docs/far_field.md): figures that say whether the
// coupled answer can stand for the pure-MPM one. Each is checked every few steps, peaks are
// kept for summary.json, and each warns once when it passes its bound; a failed far-field
// point stops the run unless the deck lets it go on.
#pragma once

#include "coupling/hybrid_solver.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace vulnus::simulator
{
struct MonitorReading
{
  const char* name;
  const char* meaning; ///< what passing the bound means, for the warning
  double value = 0.0;
  double bound = 0.0;
  double peak = 0.0;
  bool warned = false;
};

class HybridMonitors
{
public:
  HybridMonitors();

  /// Every check interval, or with `all`: reads every monitor; after other steps the failed
  /// far-field points only (a count the FE side keeps). Returns the warnings to record now.
  /// Throws mpm::BlowUp when a far-field point has failed and Hybrid/Stop when FE points fail
  /// is on. Collective.
  static constexpr std::uint64_t check_interval = 10;
  std::vector<std::string> check(const coupling::HybridSolver& solver, double initial_energy,
                                 bool all);
  /// Every monitor's peak and bound.
  nlohmann::json summary() const;
  /// Peaks and warned flags, for checkpoints (a restart then reports what the run saw).
  void save(std::ostream& out) const;
  void restore(std::istream& in);

private:
  std::vector<MonitorReading> readings;
};
} // namespace vulnus::simulator
