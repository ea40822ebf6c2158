// Where an MPM zone ends along the projectile's flight line inside the body it is cut from: the
// zone face the line leaves through before it reaches the body's own far face. A hybrid deck
// may end its zone there (coupling/decomposition.cc); the run stops before the projectile
// reaches that face (simulator/zone_end_guard.cc).
#pragma once

#include "mpm/scene_parameters.h"

#include <array>

namespace vulnus::coupling
{
/// "x", "y" or "z" for axis d, as the messages about a zone's bounds name it.
inline const char* axis_name(const int d) { return d == 0 ? "x" : (d == 1 ? "y" : "z"); }

/// Tissue the zone keeps ahead of the projectile's front, in grid cells: one for the grid
/// support of the front's points (the contact acts on the nodes of their cells), one for the
/// tissue the front compresses and tears ahead of it, which must still be material points.
constexpr double zone_end_margin_cells = 2.0;

struct ZoneEnd
{
  /// false: the line leaves the zone where it leaves the body, or misses the zone.
  bool ends = false;
  int axis = -1;           ///< of the zone's face the line leaves through
  bool upper = true;       ///< that face is the zone's upper bound (Zone max) on `axis`
  double coordinate = 0.0; ///< of that face on `axis`, m
  /// Along the line from its origin, m: where it leaves the zone (may be negative: behind the
  /// origin), and where it enters the body.
  double distance = 0.0;
  double body_entry = 0.0;
  /// x . direction of the end's point on the line, m.
  double along = 0.0;

  /// Whether x lies beyond the end's face, outside the zone.
  bool passed_by(const mpm::Vector3& x) const
  {
    return ends && (upper ? x[axis] > coordinate : x[axis] < coordinate);
  }
};

/// The end of the box zone [zone_min, zone_max] along the line origin + s direction (unit) inside
/// the body box [body_min, body_max]; a zone face within `tolerance` of the body's face on its
/// axis is the body's face.
ZoneEnd zone_end_along_line(const std::array<double, 3>& zone_min,
                            const std::array<double, 3>& zone_max, const mpm::Vector3& body_min,
                            const mpm::Vector3& body_max, const mpm::Vector3& origin,
                            const mpm::Vector3& direction, double tolerance);
} // namespace vulnus::coupling
