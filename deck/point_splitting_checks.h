// Checks of a deck that splits stretched points (Grid/Point splitting above 0): the grid and
// shape functions a split halves a point's domain on, and a limit above every deformable
// body's seeding, whose points would otherwise all split at the first step.
#pragma once

#include "deck/line_index.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// Problems as `<where>: <entry>: <problem>; <remedy>` (empty when fine or splitting is off).
std::vector<std::string> check_point_splitting(const RunParameters& parameters,
                                               const EntryLocator& locator);
} // namespace vulnus::deck
