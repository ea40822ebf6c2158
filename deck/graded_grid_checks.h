// Checks of a deck with a graded grid (Grid/Grading/Largest cell above 1): the methods that
// read a uniform cell, and a fine box that does not hold the projectile, are refused.
#pragma once

#include "deck/line_index.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// Problems as `<where>: <entry>: <problem>; <remedy>` (empty when fine or not graded).
std::vector<std::string> check_graded_grid(const RunParameters& parameters,
                                           const EntryLocator& locator);
} // namespace vulnus::deck
