// Fills bodies with material points from their geometry in the deck: box, cylinder with a
// flat or hemispherical nose (the bullet), sphere; n x n x n points per grid cell.
#pragma once

#include "mpm/grid.h"
#include "mpm/particles.h"
#include "mpm/scene_parameters.h"

#include <functional>

namespace vulnus::mpm
{
/// True when x lies inside the body's shape.
bool body_contains(const BodyParameters& body, const Vector3& x);

/// Volume of the body's shape, m^3 (its points' volumes sum to it only up to the sampling).
double body_volume(const BodyParameters& body);

/// Axis-aligned bounding box of the body's shape.
void body_bounding_box(const BodyParameters& body, Vector3& lower, Vector3& upper);

/// Gap between the body's bounding box and the domain face `face` (x-, x+, y-, y+, z-, z+ as
/// 0 to 5), m: at most the shape's own gap; 0 or less where it touches or crosses the face.
double gap_to_domain_face(const SceneParameters& scene, const BodyParameters& body, int face);

/// Appends the points of every body, one body after another, to `particles`. Points sit at
/// the centres of the n^3 sub-cells of every grid cell whose sub-cell centre is inside the
/// shape. Throws std::invalid_argument when a body has no point (smaller than a sub-cell).
/// With `keep`, only the points where keep(x) holds are stored (one rank's slab); a point's
/// id is its index among all points either way. Points of body b get a plastic history when
/// plastic_history[b] is set (the vector may be empty: none).
void build_bodies(const SceneParameters& scene, const Grid& grid, Particles& particles,
                  const std::vector<char>& plastic_history = {},
                  const std::function<bool(const Vector3&)>& keep = {});

/// Calls visit(x) for every point build_bodies creates, in the same order, storing nothing.
void visit_body_points(const SceneParameters& scene, const Grid& grid,
                       const std::function<void(const Vector3&)>& visit);
} // namespace vulnus::mpm
