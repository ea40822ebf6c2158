// Cross-entry checks of a deck (issue 9 grows this list).
#include "app/deck_checks.h"

#include "materials/material_registry.h"

#include <cctype>
#include <cmath>
#include <sstream>

namespace vulnus::app
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

std::string trim(const std::string& s)
{
  const std::size_t begin = s.find_first_not_of(' ');
  return begin == std::string::npos ? std::string()
                                    : s.substr(begin, s.find_last_not_of(' ') - begin + 1);
}

std::string point(const Vector3& p)
{
  return number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]);
}

class Checker
{
public:
  Checker(const EntryLocator& locator) : locator(locator) {}

  /// Report `problem` about `entry` unless `ok`.
  void require(const bool ok, const std::string& entry, const std::string& problem,
               const std::string& remedy)
  {
    if (!ok)
      messages.push_back(locator.where(entry) + ": " + entry + ": " + problem + "; " + remedy);
  }

  std::vector<std::string> messages;

private:
  const EntryLocator& locator;
};

/// Axis-aligned bounding box of a body's geometry.
void bounding_box(const mpm::BodyParameters& body, Vector3& lower, Vector3& upper)
{
  switch (body.shape)
  {
  case mpm::BodyShape::box:
    lower = body.box_min;
    upper = body.box_max;
    return;
  case mpm::BodyShape::sphere:
    lower = body.center - Vector3::Constant(body.radius);
    upper = body.center + Vector3::Constant(body.radius);
    return;
  case mpm::BodyShape::cylinder:
  {
    const Vector3 axis = body.axis.normalized();
    const Vector3 tip = body.center + body.length * axis;
    for (unsigned int d = 0; d < 3; ++d)
    {
      const double extent = body.radius * std::sqrt(std::max(0.0, 1.0 - axis[d] * axis[d]));
      lower[d] = std::min(body.center[d], tip[d]) - extent;
      upper[d] = std::max(body.center[d], tip[d]) + extent;
    }
    return;
  }
  }
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

void check_time(const RunParameters& p, Checker& check)
{
  const mpm::SceneParameters& scene = p.scene;
  check.require(scene.end_time > 0.0, "Time/End time", "must be > 0 (got 0)",
                "give the simulated end time in s, e.g. 3e-4");
  check.require(scene.cfl > 0.0, "Time/CFL", "must be in (0, 1] (got 0)",
                "use e.g. 0.4; smaller values are more stable");
  check.require(scene.max_time_step > 0.0, "Time/Maximum time step", "must be > 0 (got 0)",
                "give a cap in s, or 1 for no practical cap");
  check.require(scene.min_time_step < scene.max_time_step, "Time/Minimum time step",
                "must be below Time/Maximum time step (got " + number(scene.min_time_step) +
                    " >= " + number(scene.max_time_step) + ")",
                "lower it, e.g. 1e-12");
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
    for (const std::string& message : materials::check_parameters(material.parameters))
    {
      // Messages start with the entry name ("c1: ..."): locate it in the model's subsection.
      const std::size_t colon = message.find(':');
      const std::string entry = colon == std::string::npos ? "" : message.substr(0, colon);
      const std::string model = section + "/" + model_subsection(material.parameters.model);
      std::string path = section + "/Model";
      if (entry == "Matrix shear limit" || entry == "Fiber stretch limit" ||
          entry == "Shear measure" || entry == "Enabled")
        path = model + "/Failure/" + entry;
      else if (!entry.empty() && entry != "Model")
        path = model + "/" + entry;
      const std::string rest = colon == std::string::npos ? message : message.substr(colon + 1);
      const std::size_t semicolon = rest.find(';');
      const std::string problem = trim(rest.substr(0, semicolon));
      const std::string remedy = semicolon == std::string::npos ? "see `vulnus --print-parameters`"
                                                                : trim(rest.substr(semicolon + 1));
      check.require(false, path, problem, remedy);
    }
  }
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
    bool known = false;
    for (const mpm::NamedMaterial& material : scene.materials)
      known = known || material.name == body.material;
    check.require(known, section + "Material",
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
      bounding_box(body, lower, upper);
      const double tolerance = 1e-9 * (scene.domain_max - scene.domain_min).norm();
      bool inside = true;
      for (unsigned int d = 0; d < 3; ++d)
        inside = inside && lower[d] >= scene.domain_min[d] - tolerance &&
                 upper[d] <= scene.domain_max[d] + tolerance;
      check.require(inside, section + (body.shape == mpm::BodyShape::box ? "Box min" : "Center"),
                    "the body (bounding box " + point(lower) + " to " + point(upper) +
                        ") is not inside the grid domain " + point(scene.domain_min) + " to " +
                        point(scene.domain_max),
                    "move the body or enlarge Grid/Domain min and Grid/Domain max");
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
} // namespace

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
  check_bodies(parameters.scene, check);
  return check.messages;
}
} // namespace vulnus::app
