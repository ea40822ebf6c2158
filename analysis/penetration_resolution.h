// Whether a penetration depth is resolved at the run's cell. Rule (stated in
// docs/guide/run-a-scene.md): the projectile spans at least `projectile_cells_needed` cells
// across its width normal to its flight. At 20 cells across, the steady force on a sphere
// driven through a strengthless medium or the calibrated gelatin is within 5 % of its limit,
// and the depth, the integral of that force, with it; at 10 cells across it is 10-14 % off
// (docs/drag.md).
#pragma once

#include "scene/scene_description.h"

#include <string>

namespace vulnus::analysis
{
/// Cells across the projectile's width at which its depth is taken as resolved.
constexpr double projectile_cells_needed = 20.0;

struct PenetrationResolution
{
  double width_m = 0.0;      ///< the projectile's width normal to its flight
  double cells_across = 0.0; ///< width over the cell
  bool resolved = false;
  std::string reason; ///< why not, when not
};

/// The projectile's width normal to its initial velocity: a sphere's or a cylinder's diameter,
/// a box's narrowest extent across the axis nearest to that velocity (any axis when at rest).
double projectile_width(const scene::BodyParameters& projectile);

PenetrationResolution resolve_penetration(const scene::BodyParameters& projectile,
                                          double cell_size);
} // namespace vulnus::analysis
