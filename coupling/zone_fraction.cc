// The share of the split body the MPM zone has held, averaged over the run: the zone is a box
// that stays put between conversions, so the average is a sum over those intervals.
#include "coupling/hybrid_solver.h"

#include <algorithm>

namespace vulnus::coupling
{
namespace
{
/// The volume of the box [lo, hi] inside the body's box [body_min, body_max].
double volume_inside(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                     const std::array<double, 3>& body_min, const std::array<double, 3>& body_max)
{
  double volume = 1.0;
  for (int d = 0; d < 3; ++d)
    volume *= std::max(0.0, std::min(hi[d], body_max[d]) - std::max(lo[d], body_min[d]));
  return volume;
}
} // namespace

double HybridSolver::time_averaged_zone_fraction() const
{
  const std::array<double, 3>& body_min = split.fe.slab_min;
  const std::array<double, 3>& body_max = split.fe.slab_max;
  const double body = volume_inside(body_min, body_max, body_min, body_max);
  const double end = mpm_solver->time();
  if (!(body > 0.0))
    return 0.0;
  if (!(end > 0.0))
    return volume_inside(start_zone_min, start_zone_max, body_min, body_max) / body;
  double held = 0.0, since = 0.0;
  std::array<double, 3> lo = start_zone_min, hi = start_zone_max;
  for (const ZoneConversion& c : zone_conversions)
  {
    held += (c.time - since) * volume_inside(lo, hi, body_min, body_max);
    since = c.time;
    lo = c.zone_min;
    hi = c.zone_max;
  }
  held += (end - since) * volume_inside(lo, hi, body_min, body_max);
  return held / (end * body);
}
} // namespace vulnus::coupling
