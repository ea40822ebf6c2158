// A hybrid zone that ends along the projectile's path inside the target (coupling/zone_end.h):
// the note a run and `vulnus check` give before the first step, and the guard that stops the
// run when the projectile's front comes within two cells of the zone's end. Beyond the end the
// tissue is finite elements, which the projectile cannot enter.
#pragma once

#include "coupling/hybrid_solver.h"
#include "deck/run_parameters.h"

#include <string>

namespace vulnus::simulator
{
/// Where the zone ends along the path and when the run stops; "" when the zone reaches the
/// target's far face along the path, or without a projectile.
std::string zone_end_note(const coupling::HybridScene& split);
/// The same for a deck ("" unless it is a hybrid one). Call after the deck's checks passed.
std::string zone_end_note(const deck::RunParameters& parameters);

/// Collective, after every step: throws BlowUp when the projectile's nose (as the MPM solver
/// records it for the penetration) plus two cells lies past the end of the zone as it stands now
/// (an adaptive zone moves its end as it grows).
void check_zone_end(const coupling::HybridSolver& solver);
} // namespace vulnus::simulator
