// Checks of an axisymmetric deck (Grid/Dimension = axisymmetric): every body, velocity,
// material and face must turn about the y axis, and the method must be one that runs in the
// r-y half plane.
#pragma once

#include "deck/line_index.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// Problems as `<where>: <entry>: <problem>; <remedy>` (empty when fine or not axisymmetric).
std::vector<std::string> check_axisymmetric(const RunParameters& parameters,
                                            const EntryLocator& locator);
} // namespace vulnus::deck
