// Cross-entry checks of a deck.
#include "deck/deck_checks.h"
#include "deck/entry_checker.h"

#include "io/mpi_launch.h"
#include "mpm/slab_partition.h"

#include "deck/scene_size.h"
#include "materials/material_registry.h"
#include "mpm/body_builder.h"
#include "mpm/nonlocal_failure.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

namespace vulnus::deck
{
namespace
{
using Vector3 = Eigen::Vector3d;

std::string number(const double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string point(const Vector3& p)
{
  return number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]);
}


/// A size that guarantees a material point inside the body when it is at least the point
/// spacing s: the smallest box edge; for round shapes the diameter of the largest ball inside,
/// divided by sqrt(3) (a ball of radius sqrt(3)/2 s always holds a point of a lattice of
/// spacing s).
double resolvable_size(const mpm::BodyParameters& body)
{
  const double r = body.radius, L = body.length;
  switch (body.shape)
  {
  case mpm::BodyShape::box:
    return (body.box_max - body.box_min).minCoeff();
  case mpm::BodyShape::sphere:
    return 2.0 * r / std::sqrt(3.0);
  case mpm::BodyShape::cylinder:
  {
    const double ball = body.nose == mpm::NoseShape::flat ? std::min(r, 0.5 * L)
                                                          : std::max(std::min(r, L - r), 0.5 * r);
    return 2.0 * ball / std::sqrt(3.0);
  }
  }
  return 0.0;
}

void check_grid(const mpm::SceneParameters& scene, Checker& check)
{
  check.require(scene.cell_size > 0.0, "Grid/Cell size", "must be > 0 (got 0)",
                "give the cell edge length in m, e.g. 0.001");
  for (unsigned int d = 0; d < 3; ++d)
    if (!(scene.domain_max[d] > scene.domain_min[d]))
    {
      check.require(false, "Grid/Domain max",
                    "must exceed Grid/Domain min in every coordinate (got " +
                        point(scene.domain_max) + " and " + point(scene.domain_min) + ")",
                    "swap or correct the corners");
      break;
    }
}

/// A distributed MPM or hybrid run gives each rank a slab of at least
/// mpm::SlabPartition::min_layers_per_rank cell layers along one axis.
void check_rank_count(const mpm::SceneParameters& scene, Checker& check)
{
  const int n_ranks = io::launcher_size();
  if (n_ranks <= 1 || !(scene.cell_size > 0.0))
    return;
  const std::array<int, 3> cells =
    mpm::Grid::cell_counts(scene.domain_min, scene.domain_max, scene.cell_size);
  const long widest = *std::max_element(cells.begin(), cells.end());
  const long needed = long(n_ranks) * mpm::SlabPartition::min_layers_per_rank;
  check.require(widest >= needed, "Grid/Cell size",
                "the grid has at most " + std::to_string(widest) +
                  " cell layers along an axis, fewer than " +
                  std::to_string(mpm::SlabPartition::min_layers_per_rank) + " per rank for " +
                  std::to_string(n_ranks) + " MPI ranks (each rank takes a slab of layers)",
                "run on at most " + std::to_string(widest / mpm::SlabPartition::min_layers_per_rank) +
                  " ranks or use smaller cells");
}

void check_time(const RunParameters& p, Checker& check)
{
  const mpm::SceneParameters& scene = p.scene;
  check.require(scene.end_time > 0.0, "Time/End time", "must be > 0 (got 0)",
                "give the simulated end time in s, e.g. 3e-4");
  check.require(scene.cfl > 0.0, "Time/CFL", "must be in (0, 1] (got 0)",
                "use e.g. 0.4; smaller values are more stable");
  check.require(scene.rigid_projectile_stress_limit > 0.0, "Time/Rigid projectile stress limit",
                "must be in (0, 1] (got 0)",
                "use e.g. 0.5, or Time/Rigid projectile while elastic = false to keep the "
                "projectile deformable");
  check.require(scene.max_time_step > 0.0, "Time/Maximum time step", "must be > 0 (got 0)",
                "give a cap in s, or 1 for no practical cap");
  check.require(scene.min_time_step < scene.max_time_step, "Time/Minimum time step",
                "must be below Time/Maximum time step (got " + number(scene.min_time_step) +
                    " >= " + number(scene.max_time_step) + ")",
                "lower it, e.g. " + number(1e-3 * scene.max_time_step));
  check.require(!(scene.end_time > 0.0) || scene.min_time_step < scene.end_time,
                "Time/Minimum time step",
                "must be below Time/End time (got " + number(scene.min_time_step) +
                    " >= " + number(scene.end_time) + "), so the first step would already stop "
                    "the run as a collapsed step",
                "lower it, e.g. " + number(1e-3 * scene.end_time));
  const EnergyGuardParameters& guard = p.energy_guard;
  check.require_all(guard.warning <= 0.0 || guard.limit <= 0.0 || guard.warning < guard.limit,
                    {"Time/Energy balance warning", "Time/Energy balance limit"},
                    "the warning bound (" + number(guard.warning) + ") must be below the limit (" +
                      number(guard.limit) + "), or the run would stop before it warns",
                    "lower the warning (default 0.05) or raise the limit (default 0.3)");
  check.require(p.output.particle_interval <= scene.end_time, "Output/Particle output interval",
                "exceeds Time/End time (" + number(p.output.particle_interval) + " > " +
                    number(scene.end_time) + "), so no particle output would be written in between",
                "make it at most the end time, or 0 for the first and last states only");
}

void check_materials(const mpm::SceneParameters& scene, Checker& check)
{
  for (const mpm::NamedMaterial& material : scene.materials)
  {
    const std::string section = "Material " + material.name;
    for (const ParameterProblem& problem : materials::check_parameters(material.parameters))
    {
      // Parameters are named as in the model's subsection ("c1", "Failure/Matrix shear limit").
      const std::string& parameter = problem.parameters.front();
      const std::string path =
        parameter == "Model"
          ? section + "/Model"
          : section + "/" + model_subsection(material.parameters.model) + "/" + parameter;
      check.require(false, path, problem.problem,
                    problem.remedy.empty() ? "see `vulnus --print-parameters`" : problem.remedy);
    }
  }
}

/// The nonlocal failure criterion: a length that spans more than the point itself, on one
/// rank (its neighbour search holds one rank's points).
void check_failure_regularization(const mpm::SceneParameters& scene, Checker& check)
{
  for (const mpm::NamedMaterial& material : scene.materials)
  {
    const materials::FailureParameters& failure = material.parameters.tissue.failure;
    const bool tissue = material.parameters.model.find("hyperelastic") != std::string::npos;
    if (!tissue)
      continue;
    const std::string entry = "Material " + material.name + "/" +
                              model_subsection(material.parameters.model) +
                              "/Failure/Regularization length";
    for (const ParameterProblem& p :
         mpm::check_regularization(failure, scene.cell_size, io::launcher_size()))
      check.require(false, entry, p.problem, p.remedy);
  }
}

/// Uintah's contact rules: the compression criterion gathers a nodal stress that ranks do not
/// exchange; the first pass assumes USL's one projection (under MUSL's re-projection it
/// stopped the reference bullet: 18 against 101 m/s, docs/uintah_side_by_side.md).
void check_contact_criterion(const mpm::SceneParameters& scene, Checker& check)
{
  if (scene.contact.hold_compressed_surfaces && io::launcher_size() > 1)
    check.require(false, "Contact/Criterion",
                  "'approach or compression' runs on one MPI rank (its nodal stress is not "
                  "exchanged between ranks)",
                  "run on one rank (threads are fine) or use Criterion = approach");
  if (scene.contact.two_passes && scene.update_scheme != mpm::UpdateScheme::usl)
    check.require(false, "Contact/Passes",
                  "'two' needs Grid/Update scheme = USL (Uintah's scheme; MUSL re-projects the "
                  "velocities the first pass corrected)",
                  "set Grid/Update scheme = USL, or Passes = one");
  // A rigid body takes no share of the first pass (its momentum change is not booked), so
  // the other bodies' points, whose FLIP increments leave that pass out, pass through it.
  for (const mpm::BodyParameters& body : scene.bodies)
    if (scene.contact.two_passes && body_is_rigid(scene, body))
      check.require(false, "Contact/Passes",
                    "'two' does not apply to the rigid body '" + body.name +
                      "' (Uintah's friction contact is for deformable bodies; with Uintah's "
                      "other choices a rigid bullet kept 149 of 150 m/s where the deformable one "
                      "slowed to 101)",
                    "use Passes = one, or a deformable material for '" + body.name + "'");
}

void check_bodies(const mpm::SceneParameters& scene, Checker& check)
{
  std::string material_names;
  for (const mpm::NamedMaterial& material : scene.materials)
    material_names += (material_names.empty() ? "" : ", ") + material.name;

  unsigned int n_projectiles = 0;
  for (const mpm::BodyParameters& body : scene.bodies)
  {
    const std::string section = "Body " + body.name + "/";
    check.require(mpm::find_material(scene, body.material) != nullptr, section + "Material",
                  body.material.empty() ? "not given" : "no material named '" + body.material + "'",
                  "use one of the names in Scene/Materials (" + material_names + ")");
    check.require(body.density > 0.0, section + "Density", "must be > 0 (got 0)",
                  "give the mass density in kg/m^3, e.g. 1060");

    bool shape_ok = true;
    if (body.shape == mpm::BodyShape::box)
    {
      for (unsigned int d = 0; d < 3; ++d)
        shape_ok = shape_ok && body.box_max[d] > body.box_min[d];
      check.require(shape_ok, section + "Box max",
                    "must exceed Box min in every coordinate (got " + point(body.box_max) +
                        " and " + point(body.box_min) + ")",
                    "give the box corners in m");
    }
    else
    {
      shape_ok = body.radius > 0.0;
      check.require(shape_ok, section + "Radius",
                    "must be > 0 for a " +
                        std::string(body.shape == mpm::BodyShape::sphere ? "sphere" : "cylinder"),
                    "give the radius in m, e.g. 0.0045");
    }
    if (body.shape == mpm::BodyShape::cylinder)
    {
      const double min_length = body.nose == mpm::NoseShape::hemispherical ? body.radius : 0.0;
      const bool length_ok = body.length > min_length;
      check.require(length_ok, section + "Length",
                    "must exceed " +
                        std::string(body.nose == mpm::NoseShape::hemispherical
                                        ? "the radius (the hemispherical nose is part of it)"
                                        : "0") +
                        " (got " + number(body.length) + ")",
                    "give the overall length in m, e.g. 0.015");
      const bool axis_ok = body.axis.norm() > 0.0;
      check.require(axis_ok, section + "Axis", "must not be zero", "give e.g. 0, 1, 0");
      shape_ok = shape_ok && length_ok && axis_ok;
    }
    if (shape_ok)
    {
      Vector3 lower, upper;
      mpm::body_bounding_box(body, lower, upper);
      const double tolerance = 1e-9 * (scene.domain_max - scene.domain_min).norm();
      bool inside = true;
      for (unsigned int d = 0; d < 3; ++d)
      {
        // A body may reach across a mirror plane (deck/symmetry_checks.h), not lie beyond it.
        const bool lower_mirror = scene.domain_faces[2 * d] == mpm::FaceCondition::symmetry;
        const bool upper_mirror = scene.domain_faces[2 * d + 1] == mpm::FaceCondition::symmetry;
        inside = inside &&
                 (lower[d] >= scene.domain_min[d] - tolerance ||
                  (lower_mirror && upper[d] > scene.domain_min[d] + tolerance)) &&
                 (upper[d] <= scene.domain_max[d] + tolerance ||
                  (upper_mirror && lower[d] < scene.domain_max[d] - tolerance));
      }
      check.require(inside, section + (body.shape == mpm::BodyShape::box ? "Box min" : "Center"),
                    "the body (bounding box " + point(lower) + " to " + point(upper) +
                        ") is not inside the grid domain " + point(scene.domain_min) + " to " +
                        point(scene.domain_max),
                    "move the body or enlarge Grid/Domain min and Grid/Domain max");
      if (scene.cell_size > 0.0 && body.particles_per_cell > 0)
      {
        const double spacing = scene.cell_size / body.particles_per_cell;
        const double size = resolvable_size(body);
        check.require_all(size >= spacing,
                          {section + (body.shape == mpm::BodyShape::box ? "Box max" : "Radius"),
                           section + "Particles per cell", "Grid/Cell size"},
                          "body '" + body.name + "' is too small for its point spacing " +
                            number(spacing) + " m (cell size / particles per cell; the body's " +
                            "smallest size is " + number(size) + " m), so it may hold no point",
                          "use smaller cells or more Particles per cell, or enlarge the body");
      }
    }

    if (body.fibers.kind == materials::FiberFieldParameters::Kind::rotating)
    {
      check.require(body.fibers.axis.norm() > 0.0, section + "Fiber field/Axis", "must not be zero",
                    "give the through-thickness axis, e.g. 0, 1, 0");
      check.require(body.fibers.end_coordinate != body.fibers.start_coordinate,
                    section + "Fiber field/End", "must differ from Fiber field/Start",
                    "give the coordinates of the entrance and exit faces along the axis");
    }
    check.require(body.fibers.direction.norm() > 0.0, section + "Fiber field/Direction",
                  "must not be zero", "give a fiber direction, e.g. 1, 0, 0");
    if (body.is_projectile)
    {
      ++n_projectiles;
      check.require(n_projectiles == 1, section + "Projectile",
                    "more than one body is marked as the projectile",
                    "set Projectile = true for one body only");
    }
  }
}
bool shape_is_valid(const mpm::BodyParameters& body)
{
  if (body.shape == mpm::BodyShape::box)
    return (body.box_max - body.box_min).minCoeff() > 0.0;
  if (body.radius <= 0.0)
    return false;
  return body.shape == mpm::BodyShape::sphere ||
         (body.axis.norm() > 0.0 && body.length > (body.nose == mpm::NoseShape::hemispherical
                                                      ? body.radius
                                                      : 0.0));
}

/// Depth by which two bodies interpenetrate (<= 0: apart): exact for box-box and
/// sphere-box, by bounding boxes otherwise (conservative for cylinders off the axes).
double overlap_depth(const mpm::BodyParameters& a, const mpm::BodyParameters& b)
{
  if (a.shape == mpm::BodyShape::sphere && b.shape == mpm::BodyShape::box)
    return overlap_depth(b, a);
  if (a.shape == mpm::BodyShape::box && b.shape == mpm::BodyShape::sphere)
  {
    const Vector3 nearest = b.center.cwiseMax(a.box_min).cwiseMin(a.box_max);
    return b.radius - (b.center - nearest).norm();
  }
  Vector3 lower_a, upper_a, lower_b, upper_b;
  mpm::body_bounding_box(a, lower_a, upper_a);
  mpm::body_bounding_box(b, lower_b, upper_b);
  return (upper_a.cwiseMin(upper_b) - lower_a.cwiseMax(lower_b)).minCoeff();
}

/// True when the ray origin + t direction (t >= 0) meets the box [lower, upper].
bool ray_meets_box(const Vector3& origin, const Vector3& direction, const Vector3& lower,
                   const Vector3& upper)
{
  double enter = 0.0, leave = std::numeric_limits<double>::infinity();
  for (unsigned int d = 0; d < 3; ++d)
  {
    if (direction[d] == 0.0)
    {
      if (origin[d] < lower[d] || origin[d] > upper[d])
        return false;
      continue;
    }
    double t0 = (lower[d] - origin[d]) / direction[d], t1 = (upper[d] - origin[d]) / direction[d];
    if (t0 > t1)
      std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

/// Bodies that interpenetrate at the start, and a projectile whose flight misses every
/// other body (its swept bounding box never meets theirs).
void check_body_layout(const mpm::SceneParameters& scene, Checker& check)
{
  const double tolerance = 1e-3 * scene.cell_size;
  const auto& bodies = scene.bodies;
  for (std::size_t i = 0; i < bodies.size(); ++i)
    for (std::size_t j = i + 1; j < bodies.size(); ++j)
    {
      if (!shape_is_valid(bodies[i]) || !shape_is_valid(bodies[j]))
        continue;
      const double depth = overlap_depth(bodies[i], bodies[j]);
      auto placement = [](const mpm::BodyParameters& body)
      { return "Body " + body.name + (body.shape == mpm::BodyShape::box ? "/Box min" : "/Center"); };
      check.require_all(depth <= tolerance, {placement(bodies[j]), placement(bodies[i])},
                    "bodies '" + bodies[i].name + "' and '" + bodies[j].name +
                      "' overlap at the start (by " + number(depth) + " m)",
                    "move them apart: material points of two bodies cannot share space");
    }

  for (const mpm::BodyParameters& projectile : bodies)
  {
    if (!projectile.is_projectile || !shape_is_valid(projectile))
      continue;
    const std::string entry = "Body " + projectile.name + "/Initial velocity";
    bool anything_moves = false;
    for (const mpm::BodyParameters& body : bodies)
      anything_moves = anything_moves || body.initial_velocity.norm() > 0.0;
    check.require(anything_moves, entry,
                  "the projectile and every other body are at rest, so nothing would happen",
                  "give the projectile its muzzle velocity, e.g. 0, 150, 0 (m/s)");
    if (projectile.initial_velocity.norm() == 0.0 || bodies.size() < 2)
      continue;
    Vector3 lower, upper;
    mpm::body_bounding_box(projectile, lower, upper);
    const Vector3 half = 0.5 * (upper - lower), centre = 0.5 * (upper + lower);
    bool meets = false;
    for (const mpm::BodyParameters& target : bodies)
    {
      if (&target == &projectile || !shape_is_valid(target))
        continue;
      Vector3 target_lower, target_upper;
      mpm::body_bounding_box(target, target_lower, target_upper);
      meets = meets || ray_meets_box(centre, projectile.initial_velocity - target.initial_velocity,
                                     target_lower - half, target_upper + half);
    }
    check.require(meets, entry,
                  "the projectile's flight path (from " + point(centre) + " along " +
                    point(projectile.initial_velocity) + ") misses every other body",
                  "aim the velocity at the target, or move the projectile in front of it");
  }
}
/// A scene larger than this machine's memory is refused before anything is allocated.
void check_scene_size(const mpm::SceneParameters& scene, Checker& check)
{
  if (!(scene.cell_size > 0.0) || !((scene.domain_max - scene.domain_min).minCoeff() > 0.0))
    return;
  for (const mpm::BodyParameters& body : scene.bodies)
    if (!shape_is_valid(body))
      return;
  const SceneSize size = estimate_scene_size(scene);
  const double memory = physical_memory_bytes();
  const double gb = 1.0e9;
  check.require_all(
    size.box_nodes < double(std::int64_t(1) << 31) && (memory == 0.0 || size.bytes < memory),
    {"Grid/Cell size", "Grid/Domain min", "Grid/Domain max"},
    "the scene is too large for this machine (about " + number(size.points) + " points, " +
      number(size.box_nodes) + " grid nodes, " + number(size.bytes / gb) + " GB; the machine has " +
      number(memory / gb) + " GB and the grid at most 2^31 nodes)",
    "use larger cells, a smaller domain or fewer Particles per cell");
}
} // namespace

bool body_is_rigid(const mpm::SceneParameters& scene, const mpm::BodyParameters& body)
{
  for (const mpm::NamedMaterial& m : scene.materials)
    if (m.name == body.material)
      return materials::create_material(m.parameters)->is_rigid();
  return false;
}

std::string model_subsection(const std::string& model)
{
  std::string name = model;
  if (!name.empty())
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  return name;
}

std::vector<std::string> check_run_parameters(const RunParameters& parameters,
                                              const EntryLocator& locator)
{
  Checker check(locator);
  check_grid(parameters.scene, check);
  check_time(parameters, check);
  check_materials(parameters.scene, check);
  check_failure_regularization(parameters.scene, check);
  check_contact_criterion(parameters.scene, check);
  check_bodies(parameters.scene, check);
  check_body_layout(parameters.scene, check);
  if (parameters.method == Method::mpm && !parameters.hybrid.enabled)
    check_scene_size(parameters.scene, check);
  if (parameters.method == Method::mpm) // pure MPM and the hybrid's MPM zone
    check_rank_count(parameters.scene, check);
  return check.messages;
}
} // namespace vulnus::deck
