// What the log says of a projectile held rigid while elastic (mpm/rigid_hold.h): at the start
// whether it is held and against which limits, and the step that released it; and of a free
// rigid projectile whose contact would have turned it (mpm/neglected_rotation.h).
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

/// summary.json's warning when Contact/Rigid surface = exact did not apply to the deformable
/// projectile for the whole run: released by the hold (its contact then takes its points) or
/// never held ("" otherwise).
std::string rigid_hold_surface_warning(const mpm::Solver& solver);

/// A free rigid projectile's neglected rotation past its limit, once: "" before it and after it
/// was reported (`reported` is set).
std::string rigid_rotation_event(const mpm::Solver& solver, bool& reported);

/// summary.json's warning when a free rigid projectile's neglected rotation passed its limit
/// ("" otherwise).
std::string rigid_rotation_warning(const mpm::Solver& solver);
} // namespace vulnus::simulator
