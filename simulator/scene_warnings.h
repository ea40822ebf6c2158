// Warnings a run (and `vulnus check`) gives before its first step about a scene that will run
// but whose answer may mislead: a CFL beyond the tested range, a target narrower than the
// projectile, an exact rigid surface asked for a deformable projectile, a supported domain face
// that no body reaches.
#pragma once

#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::simulator
{
/// `has_mpm_side`: the CFL warning concerns the MPM step only.
std::vector<std::string> scene_warnings(const deck::RunParameters& parameters, bool has_mpm_side);
} // namespace vulnus::simulator
