// The deck entry of an MPM scene parameter as the solver names it (mpm::SceneParameters'
// members), so run-time failure reports can cite entries without the solver knowing the deck.
#pragma once

#include <string>

namespace vulnus::deck
{
/// "cfl" -> "Time/CFL", "domain_faces.x+" -> "Grid/Boundary conditions/x+", ...; a name the
/// deck does not know is returned unchanged.
std::string entry_of_scene_parameter(const std::string& name);
} // namespace vulnus::deck
