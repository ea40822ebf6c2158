// Checks of the discretisation choice before any work: a pure-FE scene (Scene/Method = FE)
// has one deformable box body and valid FE numerics; a hybrid scene (Hybrid/Enabled) can be
// split (zone on grid nodes, inside the body, around the bullet path).
#pragma once

#include "deck/line_index.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// Problems as `<where>: <entries>: <problem>; <remedy>` (empty when fine).
std::vector<std::string> check_method(const RunParameters& parameters, const EntryLocator& locator);

/// The FE scene of a pure-FE run (Scene/Method = FE). Call after check_method passed.
fem::FeSceneParameters pure_fe_scene(const RunParameters& parameters);
} // namespace vulnus::deck
