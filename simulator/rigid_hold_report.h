// What the log says of a projectile held rigid while elastic (mpm/rigid_hold.h): at the start
// whether it is held and against which limits, and the step that released it.
#pragma once

#include "mpm/solver.h"

#include <string>

namespace vulnus::simulator
{
/// The scene log's line on the hold ("" when the scene does not ask for it or the projectile
/// is rigid by its law).
std::string rigid_hold_scene_line(const mpm::Solver& solver);

/// The release, once: "" before it and after it was reported (`reported` is set).
std::string rigid_hold_release_event(const mpm::Solver& solver, bool& reported);

/// The closing note: the peaks the held projectile reached against the limits ("" when it was
/// never held).
std::string rigid_hold_final_note(const mpm::Solver& solver);
} // namespace vulnus::simulator
