// Checks of a deck with mirror planes (Grid/Boundary conditions = symmetry): the scene must be
// its own mirror image in each plane, and the numerics must be ones whose sums the plane's
// images complete.
#pragma once

#include "deck/line_index.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// Problems as `<where>: <entry>: <problem>; <remedy>` (empty when fine or without planes).
std::vector<std::string> check_symmetry(const RunParameters& parameters,
                                        const EntryLocator& locator);
} // namespace vulnus::deck
