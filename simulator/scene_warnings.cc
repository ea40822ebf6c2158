// Start-of-run warnings about the scene.
#include "simulator/scene_warnings.h"

#include "analysis/wound_metrics.h"
#include "mpm/body_builder.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace vulnus::simulator
{
namespace
{
using Vector3 = Eigen::Vector3d;

/// benchmarks/README.md, stability: the paper scene's energy balance error passes 5 % from
/// CFL 0.6 with the elastic-plastic bullet (1.3 % at the default 0.4).
void warn_about_cfl(const deck::RunParameters& parameters, std::vector<std::string>& warnings)
{
  constexpr double largest_tested_cfl = 0.5;
  if (parameters.scene.cfl <= largest_tested_cfl)
    return;
  std::ostringstream message;
  message << "Time/CFL = " << parameters.scene.cfl << " is above " << largest_tested_cfl
          << ": in the stability sweep (benchmarks/README.md) the paper scene gains more than "
             "5 % energy from CFL 0.6 on; check energy.balance_error or use 0.4";
  warnings.push_back(message.str());
}

/// True when the line x0 + s d (s real) passes through the box.
bool line_crosses_box(const Vector3& x0, const Vector3& d, const Vector3& lower, const Vector3& upper)
{
  double enter = -1e300, leave = 1e300;
  for (int k = 0; k < 3; ++k)
  {
    if (std::abs(d[k]) < 1e-14)
    {
      if (x0[k] < lower[k] || x0[k] > upper[k])
        return false;
      continue;
    }
    const double a = (lower[k] - x0[k]) / d[k], b = (upper[k] - x0[k]) / d[k];
    enter = std::max(enter, std::min(a, b));
    leave = std::min(leave, std::max(a, b));
  }
  return enter <= leave;
}

/// A box target whose width across the projectile's path is below the projectile's
/// diameter: the exit is then detected while the target may still sit on the nose.
void warn_about_narrow_targets(const mpm::SceneParameters& scene, std::vector<std::string>& warnings)
{
  const auto projectile = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                                       [](const mpm::BodyParameters& b) { return b.is_projectile; });
  if (projectile == scene.bodies.end() || projectile->shape == mpm::BodyShape::box ||
      !(projectile->initial_velocity.norm() > 0.0))
    return;
  const Vector3 flight = projectile->initial_velocity.normalized();
  const Vector3 across = flight.unitOrthogonal(), across_too = flight.cross(across);
  for (const mpm::BodyParameters& body : scene.bodies)
  {
    if (&body == &*projectile || body.shape != mpm::BodyShape::box ||
        !line_crosses_box(projectile->center, flight, body.box_min, body.box_max))
      continue;
    const Vector3 size = body.box_max - body.box_min;
    const double width = std::min(size.dot(across.cwiseAbs()), size.dot(across_too.cwiseAbs()));
    if (width >= 2.0 * projectile->radius)
      continue;
    std::ostringstream message;
    message << "body '" << body.name << "' is " << width * 1e3 << " mm wide across the path of "
            << "projectile '" << projectile->name << "' (diameter " << 2e3 * projectile->radius
            << " mm): the exit is detected when the projectile's tail passes the target's far "
               "face, possibly with target material still on its nose, and the wound figures "
               "then describe a plug; widen the body if a wound is meant";
    warnings.push_back(message.str());
  }
}
/// Bulk over small-strain shear modulus of a law, or 0 when it has no such pair (rigid).
double bulk_over_shear(const materials::MaterialParameters& m)
{
  if (m.model == "rigid")
    return 0.0;
  if (m.model == "elastic plastic")
    return m.elastic_plastic.bulk_modulus / m.elastic_plastic.shear_modulus;
  const double mu = 2.0 * (m.tissue.c1 + m.tissue.c2);
  return mu > 0.0 ? m.tissue.bulk_modulus / mu : 0.0;
}

/// A nearly incompressible body on points or elements that each keep their own J: it locks
/// (docs/locking.md: the shear mode of a square at K / mu = 1e4 rings 5.5 to 6.5 times too fast).
void warn_about_locking(const deck::RunParameters& parameters, const bool has_mpm_side,
                        std::vector<std::string>& warnings)
{
  constexpr double locking_ratio = 1e3;
  const bool fe_side = parameters.method == deck::Method::fe || parameters.hybrid.enabled;
  for (const mpm::BodyParameters& body : parameters.scene.bodies)
  {
    const mpm::NamedMaterial* material = mpm::find_material(parameters.scene, body.material);
    if (material == nullptr)
      continue;
    const double ratio = bulk_over_shear(material->parameters);
    if (ratio < locking_ratio)
      continue;
    std::string where;
    if (has_mpm_side && !parameters.scene.cell_volume_averaging)
      where = "Grid/Volume averaging";
    if (fe_side && !parameters.far_field.volume_averaging)
      where += std::string(where.empty() ? "" : " and ") + "Far field/Volume averaging";
    if (where.empty())
      continue;
    std::ostringstream message;
    message << "body '" << body.name << "': material '" << body.material << "' has bulk:shear "
            << ratio << " (>= " << locking_ratio << ") and " << where
            << " = none: each point keeps its own volume and the tissue locks (too stiff in "
               "shear, docs/locking.md); set " << where << " = cell";
    warnings.push_back(message.str());
  }
}

/// Contact/Rigid surface = exact is a rigid body's: a projectile with a deformable law that is
/// never held rigid while elastic (Time/Rigid projectile while elastic = false) never takes it.
/// One that may be held takes it while held; whether the hold lasts is known only in the run,
/// which says so in its log and summary.json when it does not (simulator/rigid_hold_report.cc).
void warn_about_exact_surface_of_deformable_projectile(const mpm::SceneParameters& scene,
                                                       std::vector<std::string>& warnings)
{
  const mpm::BodyParameters* projectile = nullptr;
  for (const mpm::BodyParameters& body : scene.bodies)
    if (body.is_projectile)
      projectile = &body;
  if (!scene.contact.exact_rigid_surface || projectile == nullptr ||
      scene.rigid_projectile_while_elastic)
    return;
  const mpm::NamedMaterial* material = mpm::find_material(scene, projectile->material);
  if (material == nullptr || material->parameters.model == "rigid")
    return;
  std::ostringstream message;
  message << "Contact/Rigid surface = exact: projectile '" << projectile->name
          << "' has the deformable law '" << material->parameters.model
          << "' and the exact surface is a rigid body's: its contact takes its points "
             "throughout (Time/Rigid projectile while elastic = false); 'Material "
          << projectile->material << "/Model = rigid' gives it the exact surface throughout";
  warnings.push_back(message.str());
}

/// A fixed or roller domain face that no deformable body reaches at the start holds nothing
/// (and summary.json lists it with a zero impulse): MPM points reach the face's grid nodes only
/// from within one cell, and the far field takes a face's condition only where a body face
/// lies on it. (Rigid bodies take no face condition.)
void warn_about_unreached_faces(const deck::RunParameters& parameters,
                                std::vector<std::string>& warnings)
{
  const mpm::SceneParameters& scene = parameters.scene;
  const bool meshed = parameters.method == deck::Method::fe;
  const double reach = meshed ? 1e-6 * scene.cell_size : scene.cell_size;
  for (int face = 0; face < 6; ++face)
  {
    if (scene.domain_faces[face] == mpm::FaceCondition::free)
      continue;
    const mpm::BodyParameters* nearest = nullptr;
    double gap = std::numeric_limits<double>::infinity();
    for (const mpm::BodyParameters& body : scene.bodies)
    {
      const mpm::NamedMaterial* m = mpm::find_material(scene, body.material);
      if (m == nullptr || m->parameters.model == "rigid")
        continue;
      if (const double g = mpm::gap_to_domain_face(scene, body, face); g < gap)
      {
        nearest = &body;
        gap = g;
      }
    }
    if (nearest == nullptr || gap < reach)
      continue;
    std::ostringstream message;
    message << "Grid/Boundary conditions/" << analysis::box_face_name(face) << " = "
            << scene::face_condition_name(scene.domain_faces[face])
            << ": no deformable body reaches that face (the nearest, '" << nearest->name
            << "', is " << gap * 1e3 << " mm from it; "
            << (meshed ? "the finite elements take a face's condition only on a body face that "
                         "lies on it"
                       : "a face condition acts on the face's grid nodes, which points reach "
                         "only from within one cell")
            << "), so it holds nothing until a body gets there; put the face on the body "
               "(Grid/Domain min or max) or set it free";
    warnings.push_back(message.str());
  }
}
} // namespace

std::vector<std::string> scene_warnings(const deck::RunParameters& parameters, const bool has_mpm_side)
{
  std::vector<std::string> warnings;
  if (has_mpm_side)
  {
    warn_about_cfl(parameters, warnings);
    warn_about_narrow_targets(parameters.scene, warnings);
    warn_about_exact_surface_of_deformable_projectile(parameters.scene, warnings);
  }
  warn_about_locking(parameters, has_mpm_side, warnings);
  warn_about_unreached_faces(parameters, warnings);
  return warnings;
}
} // namespace vulnus::simulator
