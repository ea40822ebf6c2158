// Checks across deck entries, after every entry has matched its pattern: materials exist,
// bodies lie inside the grid, limits make sense. Messages are
// `<where>: <entry path>: <problem>; <what to do>`.
#pragma once

#include "deck/line_index.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// All problems found (empty when the parameters are usable).
std::vector<std::string> check_run_parameters(const RunParameters& parameters,
                                              const EntryLocator& locator);

/// Whether the body's law is rigid (false for an unknown material).
bool body_is_rigid(const mpm::SceneParameters& scene, const mpm::BodyParameters& body);

/// Name of the deck subsection holding a material model's entries ("Elastic plastic" for
/// the model "elastic plastic").
std::string model_subsection(const std::string& model);
} // namespace vulnus::deck
