// The end of a zone box along a straight line inside a body box.
#include "coupling/zone_end.h"

#include "mpm/target_path.h"

#include <cmath>

namespace vulnus::coupling
{
ZoneEnd zone_end_along_line(const std::array<double, 3>& zone_min,
                            const std::array<double, 3>& zone_max, const mpm::Vector3& body_min,
                            const mpm::Vector3& body_max, const mpm::Vector3& origin,
                            const mpm::Vector3& direction, const double tolerance)
{
  ZoneEnd end;
  const mpm::Vector3 lower(zone_min[0], zone_min[1], zone_min[2]);
  const mpm::Vector3 upper(zone_max[0], zone_max[1], zone_max[2]);
  const mpm::PathThroughBox body = mpm::path_through_box(body_min, body_max, origin, direction);
  const mpm::PathThroughBox zone = mpm::path_through_box(lower, upper, origin, direction);
  if (!body.hits || !zone.hits)
    return end;
  end.axis = zone.exit_face / 2;
  end.upper = zone.exit_face % 2 == 1;
  end.coordinate = end.upper ? upper[end.axis] : lower[end.axis];
  const double body_face = end.upper ? body_max[end.axis] : body_min[end.axis];
  end.ends =
      std::abs(end.coordinate - body_face) > tolerance && zone.t_out < body.t_out - tolerance;
  end.distance = zone.t_out;
  end.along = origin.dot(direction) + zone.t_out;
  end.body_entry = body.t_in;
  return end;
}
} // namespace vulnus::coupling
