// summary.json of an MPM run: counts, throughput, failure by type, wound metrics, bullet
// kinematics and the energy budget (keys listed in the wound-analysis issue and the README).
#pragma once

#include "mpm/solver.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vulnus::app
{
struct RunTotals
{
  double wall_seconds = 0.0;
  double projectile_initial_speed = 0.0;
  double projectile_initial_kinetic_energy = 0.0;
  bool completed = true;
  std::string error; ///< blow-up message when not completed
  std::vector<std::string> warnings;
};

nlohmann::json mpm_summary(const mpm::Solver& solver, const RunTotals& totals);
} // namespace vulnus::app
