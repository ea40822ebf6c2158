// The resolution rule of a penetration depth: the projectile's width in cells against
// projectile_cells_needed.
#include "analysis/penetration_resolution.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace vulnus::analysis
{
double projectile_width(const scene::BodyParameters& projectile)
{
  if (projectile.shape != scene::BodyShape::box)
    return 2.0 * projectile.radius;
  const scene::Vector3 extent = projectile.box_max - projectile.box_min;
  const scene::Vector3 v = projectile.initial_velocity.cwiseAbs();
  int flight = -1;
  if (v.maxCoeff() > 0.0)
    v.maxCoeff(&flight);
  double width = std::numeric_limits<double>::max();
  for (int d = 0; d < 3; ++d)
    if (d != flight)
      width = std::min(width, extent[d]);
  return width;
}

PenetrationResolution resolve_penetration(const scene::BodyParameters& projectile,
                                          const double cell_size)
{
  PenetrationResolution r;
  r.width_m = projectile_width(projectile);
  r.cells_across = cell_size > 0.0 ? r.width_m / cell_size : 0.0;
  r.resolved = r.cells_across >= projectile_cells_needed * (1.0 - 1e-9); // 4.4 mm / 0.22 mm is 20
  if (!r.resolved)
  {
    std::ostringstream s;
    s.precision(3);
    s << "the projectile spans " << r.cells_across << " cells across, " << projectile_cells_needed
      << " are needed for the drag within 5 % of its limit (docs/drag.md)";
    r.reason = s.str();
  }
  return r;
}
} // namespace vulnus::analysis
