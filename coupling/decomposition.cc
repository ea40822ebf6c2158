// The MPM/FE split of a hybrid scene and its checks.
#include "coupling/decomposition.h"

#include "fem/fe_scene_of_body.h"
#include "mpm/target_path.h"
#include "materials/material_registry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace vulnus::coupling
{
namespace
{
std::string format_point(const std::array<double, 3>& x)
{
  std::ostringstream s;
  s << x[0] << ", " << x[1] << ", " << x[2];
  return s.str();
}

bool is_rigid(const mpm::SceneParameters& scene, const mpm::BodyParameters& body)
{
  for (const mpm::NamedMaterial& m : scene.materials)
    if (m.name == body.material)
      return materials::create_material(m.parameters)->is_rigid();
  return false;
}

/// The projectile, with the start and direction of its flight and its radius plus one cell;
/// null without a projectile.
const mpm::BodyParameters* flight_line(const mpm::SceneParameters& scene, mpm::Vector3& start, mpm::Vector3& direction,
                 double& reach)
{
  for (const mpm::BodyParameters& body : scene.bodies)
  {
    if (!body.is_projectile)
      continue;
    reach = (body.shape == mpm::BodyShape::box ? 0.5 * (body.box_max - body.box_min).norm()
                                               : body.radius) +
            scene.cell_size;
    start = body.shape == mpm::BodyShape::box ? mpm::Vector3(0.5 * (body.box_min + body.box_max))
                                              : body.center;
    direction = body.initial_velocity;
    if (direction.norm() == 0.0)
      direction = body.axis;
    direction.normalize();
    return &body;
  }
  return nullptr;
}

/// How far the projectile's shape reaches beyond `start` along `direction`, m.
double front_beyond(const mpm::BodyParameters& projectile, const mpm::Vector3& start,
                    const mpm::Vector3& direction)
{
  return mpm::reach_along(projectile, direction) - start.dot(direction);
}

/// Where the zone ends along the flight line of the scene's projectile inside the body box.
ZoneEnd end_along_path(const mpm::SceneParameters& scene, const mpm::Vector3& body_min,
                       const mpm::Vector3& body_max, const std::array<double, 3>& zone_min,
                       const std::array<double, 3>& zone_max)
{
  mpm::Vector3 start, direction;
  double reach = 0.0;
  if (flight_line(scene, start, direction, reach) == nullptr)
    return {};
  return zone_end_along_line(zone_min, zone_max, body_min, body_max, start, direction,
                             1e-6 * scene.cell_size);
}

/// The projectile's axis must stay at least radius + one cell inside the zone wherever it
/// crosses the slab, up to where the zone ends: at a slab face, or inside the slab in the
/// direction of flight, where the run stops the projectile two cells short of the end
/// (simulator/zone_end_guard.cc). That end must then lie beyond the projectile's front and the
/// slab's face by more than those two cells.
void check_bullet_path(const mpm::SceneParameters& scene, const mpm::BodyParameters& slab,
                       const HybridParameters& hybrid, std::vector<ParameterProblem>& problems)
{
  mpm::Vector3 start, direction;
  double reach = 0.0;
  const mpm::BodyParameters* projectile = flight_line(scene, start, direction, reach);
  if (projectile == nullptr)
    return;
  const ZoneEnd end = zone_end_along_line(hybrid.zone_min, hybrid.zone_max, slab.box_min,
                                          slab.box_max, start, direction, 1e-6 * scene.cell_size);
  if (end.ends)
  {
    const double margin = zone_end_margin_cells * scene.cell_size;
    const double front = front_beyond(*projectile, start, direction);
    if (end.distance <= std::max(front, end.body_entry) + margin)
    {
      std::ostringstream s;
      s << "the zone ends at " << axis_name(end.axis) << " = " << end.coordinate
        << " m along the path of projectile '" << projectile->name << "', within "
        << zone_end_margin_cells << " cells of "
        << (front >= end.body_entry ? "the projectile's front at its start"
                                    : "where the path enters body '" + slab.name + "'")
        << ": the run would stop before the projectile enters the zone";
      problems.push_back({{end.upper ? "zone_max" : "zone_min"}, s.str(),
                          "lengthen the zone along the path, past where the projectile stops"});
      return;
    }
  }
  // Sample the flight line across the slab box, up to the zone's end.
  const double span = (slab.box_max - slab.box_min).norm() + (start - slab.box_min).norm() +
                      (start - slab.box_max).norm();
  const int n_samples = 2000;
  for (int i = 0; i <= n_samples; ++i)
  {
    const double along = span * i / n_samples;
    if (end.ends && along > end.distance)
      break;
    const mpm::Vector3 c = start + along * direction;
    bool in_slab = true;
    for (int d = 0; d < 3; ++d)
      in_slab = in_slab && c[d] >= slab.box_min[d] && c[d] <= slab.box_max[d];
    if (!in_slab)
      continue;
    for (int d = 0; d < 3; ++d)
    {
      const bool end_face = end.ends && d == end.axis;
      const bool lower_open =
        hybrid.zone_min[d] <= slab.box_min[d] + 1e-9 || (end_face && !end.upper);
      const bool upper_open =
        hybrid.zone_max[d] >= slab.box_max[d] - 1e-9 || (end_face && end.upper);
      if ((!lower_open && c[d] - reach < hybrid.zone_min[d]) ||
          (!upper_open && c[d] + reach > hybrid.zone_max[d]))
      {
        std::ostringstream s;
        s << "the path of projectile '" << projectile->name << "' at (" << c[0] << ", " << c[1]
          << ", " << c[2] << ") m comes closer than its radius plus one cell to the zone's "
          << axis_name(d) << " bounds";
        problems.push_back({{"zone_min", "zone_max"}, s.str(),
                            "widen the zone so the tract and the tissue it tears stay in MPM"});
        return;
      }
    }
  }
}

/// The grid node at or beyond x, outwards (down for a lower bound), within [lo, hi].
double node_outwards(const double x, const double origin, const double h, const bool lower,
                     const double lo, const double hi)
{
  const double cells = (x - origin) / h;
  double node = origin + h * (lower ? std::floor(cells + 1e-9) : std::ceil(cells - 1e-9));
  if (node < lo - 1e-9 * h)
    node += h;
  if (node > hi + 1e-9 * h)
    node -= h;
  return node;
}
} // namespace

HybridParameters resolve_zone(const mpm::SceneParameters& scene, const HybridParameters& hybrid)
{
  HybridParameters resolved = hybrid;
  const int index = split_body_index(scene, hybrid);
  mpm::Vector3 start, direction;
  double reach = 0.0;
  if (hybrid.zone_start != ZoneStart::around_path || index < 0 ||
      flight_line(scene, start, direction, reach) == nullptr)
    return resolved;
  const mpm::BodyParameters& slab = scene.bodies[static_cast<std::size_t>(index)];
  reach += hybrid.path_margin;
  mpm::Vector3 lo = mpm::Vector3::Constant(std::numeric_limits<double>::max());
  mpm::Vector3 hi = -lo;
  const double span = (slab.box_max - slab.box_min).norm() + (start - slab.box_min).norm() +
                      (start - slab.box_max).norm();
  const int n_samples = 4000;
  for (int i = 0; i <= n_samples; ++i)
  {
    const mpm::Vector3 c = start + (span * i / n_samples) * direction;
    bool near_slab = true;
    for (int d = 0; d < 3; ++d)
      near_slab = near_slab && c[d] >= slab.box_min[d] - reach && c[d] <= slab.box_max[d] + reach;
    if (!near_slab)
      continue;
    lo = lo.cwiseMin(c - mpm::Vector3::Constant(reach));
    hi = hi.cwiseMax(c + mpm::Vector3::Constant(reach));
  }
  if (lo[0] > hi[0])
    return resolved; // the path misses the body: check_decomposition reports it
  const double h = scene.cell_size;
  for (int d = 0; d < 3; ++d)
  {
    const double a = std::max(lo[d], slab.box_min[d]);
    const double b = std::min(hi[d], slab.box_max[d]);
    resolved.zone_min[d] = node_outwards(a, scene.domain_min[d], h, true, slab.box_min[d], slab.box_max[d]);
    resolved.zone_max[d] = node_outwards(b, scene.domain_min[d], h, false, slab.box_min[d], slab.box_max[d]);
  }
  return resolved;
}

int split_body_index(const mpm::SceneParameters& scene, const HybridParameters& hybrid)
{
  if (!hybrid.body.empty())
  {
    for (std::size_t b = 0; b < scene.bodies.size(); ++b)
      if (scene.bodies[b].name == hybrid.body)
        return static_cast<int>(b);
    return -1;
  }
  int found = -1;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
  {
    const mpm::BodyParameters& body = scene.bodies[b];
    if (body.is_projectile || body.shape != mpm::BodyShape::box || is_rigid(scene, body))
      continue;
    if (found >= 0)
      return -1; // ambiguous: Hybrid/Body must name it
    found = static_cast<int>(b);
  }
  return found;
}

ZoneEnd zone_end_along_path(const mpm::SceneParameters& scene, const HybridParameters& hybrid)
{
  const int index = split_body_index(scene, hybrid);
  if (index < 0)
    return {};
  const HybridParameters resolved = resolve_zone(scene, hybrid);
  const mpm::BodyParameters& slab = scene.bodies[static_cast<std::size_t>(index)];
  return end_along_path(scene, slab.box_min, slab.box_max, resolved.zone_min, resolved.zone_max);
}

ZoneEnd zone_end_along_path(const HybridScene& split, const std::array<double, 3>& zone_min,
                            const std::array<double, 3>& zone_max)
{
  const mpm::Vector3 body_min(split.fe.slab_min[0], split.fe.slab_min[1], split.fe.slab_min[2]);
  const mpm::Vector3 body_max(split.fe.slab_max[0], split.fe.slab_max[1], split.fe.slab_max[2]);
  return end_along_path(split.mpm, body_min, body_max, zone_min, zone_max);
}

std::vector<ParameterProblem> check_decomposition(const mpm::SceneParameters& scene,
                                                  const HybridParameters& deck_hybrid,
                                                  const fem::FeSceneParameters& far_field)
{
  std::vector<ParameterProblem> problems;
  const HybridParameters hybrid = resolve_zone(scene, deck_hybrid);
  const AdaptiveZoneParameters& adaptive = hybrid.adaptive;
  if (adaptive.enabled && !(adaptive.threshold > 0.0 && adaptive.threshold <= 1.0))
    problems.push_back({{"adaptive.threshold"}, "outside (0, 1]",
                        "a fraction of the failure limits, about 0.5"});
  if (adaptive.total_failure_rule() && !adaptive.enabled)
    problems.push_back({{"adaptive.failure"}, "total without an adaptive zone",
                        "set Hybrid/Adaptive zone = true, or Adaptive zone failure = any"});
  // A matrix-failed tissue point resists neither shear nor tension (unless its fibres are
  // stretched): a far-field cell of them must convert before it inverts.
  if (adaptive.enabled && adaptive.total_failure_rule() &&
      !(adaptive.distortion > 0.0) && !(adaptive.jacobian_ratio > 0.0))
    problems.push_back({{"adaptive.failure"},
                        "total with neither cell-motion rule on: a far-field cell whose matrix "
                        "failed has no shear stiffness and may invert before it converts",
                        "set Hybrid/Adaptive zone distortion (e.g. 0.5) or Adaptive zone corner "
                        "Jacobian ratio (e.g. 0.3) > 0, or Adaptive zone failure = any"});
  if (adaptive.enabled && !(adaptive.reach >= scene.cell_size))
    problems.push_back({{"adaptive.reach"}, "below one grid cell",
                        "give how far the zone may grow, in m"});
  if (hybrid.zone_start == ZoneStart::around_path && !(hybrid.path_margin >= 0.0))
    problems.push_back({{"path_margin"}, "negative", "give a margin >= 0 m"});
  const int index = split_body_index(scene, hybrid);
  if (index < 0)
  {
    if (hybrid.body.empty())
      problems.push_back({{"body"},
                          "no single deformable box body that is not the projectile",
                          "name the body to split between MPM and finite elements"});
    else
      problems.push_back({{"body"}, "no body named '" + hybrid.body + "'",
                          "use the name of one of the scene's bodies"});
    return problems;
  }
  const mpm::BodyParameters& slab = scene.bodies[index];
  if (slab.shape != mpm::BodyShape::box)
    problems.push_back({{"body"}, "body '" + slab.name + "' is not a box",
                        "only a box body can be split into MPM zone and FE mesh"});
  if (is_rigid(scene, slab))
    problems.push_back({{"body"}, "body '" + slab.name + "' is rigid", "split a deformable body"});
  if (slab.is_projectile)
    problems.push_back({{"body"}, "body '" + slab.name + "' is the projectile", ""});

  const double h = scene.cell_size;
  const double tolerance = 1e-6 * h;
  bool zone_inside = true;
  for (int d = 0; d < 3; ++d)
  {
    if (!(hybrid.zone_max[d] > hybrid.zone_min[d] + 0.5 * h))
    {
      problems.push_back({{"zone_min", "zone_max"},
                          std::string("the zone is empty along ") + axis_name(d),
                          "its upper bound must exceed its lower bound by at least one cell"});
      zone_inside = false;
    }
    if (hybrid.zone_min[d] < slab.box_min[d] - tolerance ||
        hybrid.zone_max[d] > slab.box_max[d] + tolerance)
      zone_inside = false;
    for (const bool lower : {true, false})
    {
      const double bound = lower ? hybrid.zone_min[d] : hybrid.zone_max[d];
      const double cells = (bound - scene.domain_min[d]) / h;
      if (std::abs(cells - std::round(cells)) * h > tolerance)
      {
        // Outwards, so the zone keeps what was asked for (an inward node can leave it too
        // small for the projectile), unless that leaves the body.
        double node = scene.domain_min[d] + (lower ? std::floor(cells) : std::ceil(cells)) * h;
        if (node < slab.box_min[d] - tolerance || node > slab.box_max[d] + tolerance)
          node = scene.domain_min[d] + (lower ? std::ceil(cells) : std::floor(cells)) * h;
        std::ostringstream s, remedy;
        s << axis_name(d) << " = " << bound
          << " m is not on a grid node (the grid's lower corner plus whole cells)";
        remedy << "move it to " << node << " m";
        problems.push_back({{"zone_min", "zone_max"}, s.str(), remedy.str()});
      }
    }
  }
  if (!zone_inside)
    problems.push_back({{"zone_min", "zone_max"},
                        "the zone (" + format_point(hybrid.zone_min) + ") to (" +
                          format_point(hybrid.zone_max) + ") m must lie inside body '" +
                          slab.name + "' (its box)",
                        ""});
  bool fills_slab = true;
  for (int d = 0; d < 3; ++d)
    fills_slab = fills_slab && hybrid.zone_min[d] <= slab.box_min[d] + tolerance &&
                 hybrid.zone_max[d] >= slab.box_max[d] - tolerance;
  if (fills_slab)
    problems.push_back({{"zone_min", "zone_max"},
                        "the zone covers the whole body '" + slab.name +
                          "', leaving no far field",
                        "shrink it or run without the hybrid"});
  if (far_field.far_cell_size < h)
    problems.push_back({{"far_field.far_cell_size"}, "smaller than the MPM grid's cell size",
                        "the far field grows from the grid spacing at the interface"});
  if (hybrid.scheme == CouplingScheme::same_step &&
      far_field.integrator != fem::TimeIntegrator::central_difference)
    problems.push_back({{"scheme", "far_field.integrator"},
                        "the same-step scheme needs the explicit central-difference far field",
                        "use the multi-step scheme for an implicit far field"});
  // The explicit far field's steps take the interface node by node; only an implicit far
  // field's windows are balanced or take the dashpot, which would otherwise change nothing.
  if (hybrid.window_coupling == WindowCoupling::dashpot &&
      far_field.integrator == fem::TimeIntegrator::central_difference)
    problems.push_back({{"window_coupling", "far_field.integrator"},
                        "'dashpot' couples the windows of an implicit far field, and the "
                        "explicit one (central difference) has none: it would change nothing",
                        "use Window coupling = balanced (the default), or Integrator = Newmark "
                        "or generalized alpha"});
  // The implicit far field's windows solve its effective interface mass node by node; a
  // following interface would need it over the grid nodes each node is spread on.
  if (hybrid.interface == InterfacePlacement::following &&
      far_field.integrator != fem::TimeIntegrator::central_difference)
    problems.push_back({{"interface", "far_field.integrator"},
                        "a following interface needs the explicit central-difference far field",
                        "use Integrator = central difference, or Interface = grid nodes"});
  if (hybrid.interface == InterfacePlacement::following && adaptive.enabled &&
      adaptive.interface_motion == InterfaceMotion::total)
    problems.push_back({{"interface", "adaptive.interface_motion"},
                        "Adaptive zone interface motion = total bounds how far an interface on "
                        "grid nodes may move; a following interface needs no such bound, and "
                        "with it the zone would grow on every wave",
                        "use Adaptive zone interface motion = non-affine, or Interface = grid "
                        "nodes"});
  if (far_field.degree != 1)
    problems.push_back({{"far_field.degree"},
                        "the interface nodes must coincide with MPM grid nodes, which needs "
                        "degree 1 in a hybrid scene",
                        ""});
  if (problems.empty())
    check_bullet_path(scene, slab, hybrid, problems);
  return problems;
}

HybridScene decompose(const mpm::SceneParameters& scene, const HybridParameters& deck_hybrid,
                      const fem::FeSceneParameters& far_field)
{
  const std::vector<ParameterProblem> problems = check_decomposition(scene, deck_hybrid, far_field);
  const HybridParameters hybrid = resolve_zone(scene, deck_hybrid);
  if (!problems.empty())
  {
    std::ostringstream message;
    for (std::size_t i = 0; i < problems.size(); ++i)
      message << (i ? "\n" : "") << "hybrid " << problems[i].parameters.front() << ": "
              << describe(problems[i]);
    throw std::invalid_argument(message.str());
  }
  HybridScene split;
  split.hybrid = hybrid;
  split.coupled_body = static_cast<std::size_t>(split_body_index(scene, hybrid));
  split.mpm = scene;
  split.mpm.deck_bodies = scene.bodies;
  mpm::BodyParameters& zone = split.mpm.bodies[split.coupled_body];
  const mpm::BodyParameters slab = zone;
  for (int d = 0; d < 3; ++d)
  {
    zone.box_min[d] = std::max(slab.box_min[d], hybrid.zone_min[d]);
    zone.box_max[d] = std::min(slab.box_max[d], hybrid.zone_max[d]);
  }

  fem::FeSceneParameters& fe = split.fe;
  fe = fem::fe_scene_of_body(scene, split.coupled_body, far_field);
  for (int d = 0; d < 3; ++d)
  {
    fe.hole_min[d] = zone.box_min[d];
    fe.hole_max[d] = zone.box_max[d];
    split.initial_velocity[d] = slab.initial_velocity[d];
  }
  fe.has_hole = true;
  split.limit_min = fe.hole_min;
  split.limit_max = fe.hole_max;
  if (hybrid.adaptive.enabled)
  {
    // Whole cells beyond the zone, as far as the reach and the body allow.
    const double h = scene.cell_size;
    const double n_reach = std::ceil(hybrid.adaptive.reach / h - 1e-9);
    for (int d = 0; d < 3; ++d)
    {
      const double below = std::floor((zone.box_min[d] - slab.box_min[d]) / h + 1e-9);
      const double above = std::floor((slab.box_max[d] - zone.box_max[d]) / h + 1e-9);
      split.limit_min[d] = zone.box_min[d] - h * std::min(n_reach, below);
      split.limit_max[d] = zone.box_max[d] + h * std::min(n_reach, above);
    }
    fe.has_focus = true;
    fe.track_failure_proximity = true;
    fe.failure_proximity = hybrid.adaptive.failure;
    fe.focus_min = split.limit_min;
    fe.focus_max = split.limit_max;
  }
  fe.interface_condition = fem::InterfaceCondition::velocity_driven;
  fe.staggered_velocity = fe.integrator == fem::TimeIntegrator::central_difference;
  return split;
}
} // namespace vulnus::coupling
