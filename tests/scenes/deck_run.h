// Running a deck of the source tree to its end in-process, for the scene tests: the deck's
// path under inputs/, the finished solver, and its energy balance error.
#pragma once

#include "deck/deck_reader.h"
#include "mpm/solver.h"

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace vulnus::scene_tests
{
inline std::string input_deck(const std::string& relative_path)
{
  const char* dir = std::getenv("VULNUS_SOURCE_DIR");
  return std::string(dir ? dir : VULNUS_DEFAULT_SOURCE_DIR) + "/inputs/" + relative_path;
}

inline std::unique_ptr<mpm::Solver> run_to_end(const std::string& deck_path,
                                               const std::vector<deck::DeckOverride>& overrides)
{
  const deck::RunParameters parameters = deck::read_run_parameters(deck_path, overrides);
  auto solver = std::make_unique<mpm::Solver>(parameters.scene);
  while (!solver->finished())
    solver->advance();
  return solver;
}

/// (kinetic + strain + dissipated + contact- and support-dissipated + removed - initial) /
/// initial.
inline double energy_balance_error(const mpm::Solver& solver, const mpm::SceneDiagnostics& d)
{
  const double accounted = d.kinetic_energy + d.strain_energy + d.dissipated_energy +
                           solver.contact_dissipation() + solver.support_dissipation() +
                           solver.removed_energy();
  return (accounted - solver.initial_energy()) / solver.initial_energy();
}
} // namespace vulnus::scene_tests
