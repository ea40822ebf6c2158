// Checks of a deck with mirror planes: what its image in a plane would not reproduce is refused
// with the entry that breaks the symmetry.
#include "deck/symmetry_checks.h"

#include "deck/deck_checks.h"
#include "deck/deck_entries.h"
#include "deck/entry_checker.h"
#include "materials/material_registry.h"
#include "mpm/body_builder.h"
#include "mpm/symmetry_planes.h"

#include <cmath>

namespace vulnus::deck
{
namespace
{
/// The numerics whose sums at the plane's nodes its images complete.
void check_numerics(const RunParameters& p, const int face, Checker& out)
{
  const mpm::SceneParameters& s = p.scene;
  const std::string entry = std::string("Grid/Boundary conditions/") + scene::face_name(face);
  if (s.axisymmetric)
    out.require(false, entry, "symmetry is for a 3D grid (an axisymmetric grid has its own planes)",
                "set Grid/Dimension = 3, or the face to free, fixed or roller");
  if (s.shape_function != mpm::ShapeFunction::linear)
    out.require(false, entry,
                "symmetry needs Grid/Shape function = linear (GIMP and CPDI points reach nodes "
                "beyond the plane, whose mirrored sums are not formed)",
                "set Grid/Shape function = linear");
  if (s.velocity_transfer == mpm::VelocityTransfer::xpic ||
      s.velocity_transfer == mpm::VelocityTransfer::fmpm)
    out.require(false, entry,
                "symmetry does not take Grid/Velocity transfer = XPIC or FMPM (their grid series "
                "would reach beyond the plane)",
                "use FLIP, PIC, APIC or a relaxed transfer");
  if (face % 2 == 1 && s.domain_faces[face - 1] == mpm::FaceCondition::symmetry)
    out.require(false, entry,
                std::string("symmetry on both ") + scene::face_name(face - 1) + " and " +
                  scene::face_name(face) + " would mirror the scene without end",
                "keep one mirror plane per axis");
  if (s.gravity[face / 2] != 0.0)
    out.require(false, "Scene/Gravity",
                std::string("gravity across the symmetry face ") + scene::face_name(face) +
                  " is not its own mirror image (got " + format_point(s.gravity) + ")",
                "set the face to free, fixed or roller, or turn gravity along the face");
}

/// A body's image in the plane must be the body: a sphere or cylinder across it centred on it,
/// the cylinder's axis in it; no velocity across it; fibres in it or normal to it.
void check_body(const mpm::SceneParameters& s, const mpm::BodyParameters& body,
                const mpm::SymmetryPlane& plane, Checker& out)
{
  const std::string section = "Body " + body.name + "/";
  const int d = plane.axis;
  const std::string face = scene::face_name(plane.face);
  const bool across = mpm::crosses(body, plane);
  if (across)
  {
    const std::string what = "body '" + body.name + "' crosses the symmetry face " + face + ", ";
    if (body.shape != mpm::BodyShape::box)
    {
      const double tolerance = 1e-9 * (s.domain_max - s.domain_min).norm();
      if (std::abs(body.center[d] - plane.coordinate) > tolerance)
        out.require(false, section + "Center",
                    what + "so its centre must lie on it (at " + format_number(plane.coordinate) +
                      " m along its normal), for its image to be its other half (got " +
                      format_point(body.center) + ")",
                    "put the centre on the face, or set the face to free, fixed or roller");
      if (body.shape == mpm::BodyShape::cylinder && std::abs(body.axis[d]) > 1e-12 * body.axis.norm())
        out.require(false, section + "Axis", what + "so its axis must lie in it",
                    "turn the axis into the face");
    }
    if (body.initial_velocity[d] != 0.0)
      out.require(false, section + "Initial velocity",
                  what + "so it cannot move across it (got " + format_point(body.initial_velocity) + ")",
                  "give it no velocity component normal to the face");
  }
  const mpm::NamedMaterial* material = scene::find_material(s, body.material);
  Eigen::Vector3d lower, upper;
  mpm::body_bounding_box(body, lower, upper);
  const bool touches = across || std::abs((plane.face % 2 == 0 ? lower[d] : upper[d]) -
                                          plane.coordinate) <= 1e-6 * s.cell_size;
  if (material == nullptr || !touches)
    return;
  if (material->parameters.model.find("hyperelastic") != std::string::npos &&
      material->parameters.tissue.failure.regularization_length > 0.0)
    out.require(false,
                "Material " + body.material + "/" + model_subsection(material->parameters.model) +
                  "/Failure/Regularization length",
                "the nonlocal failure average would miss the neighbours beyond the symmetry "
                "face " + face,
                "set it to 0, or the face to free, fixed or roller");
  if (!materials::create_material(material->parameters)->uses_fibers())
    return;
  const materials::FiberFieldParameters& fibers = body.fibers;
  const Eigen::Vector3d a = fibers.direction.normalized();
  const bool in_or_normal = std::abs(a[d]) < 1e-9 || std::abs(std::abs(a[d]) - 1.0) < 1e-9;
  if (fibers.kind == materials::FiberFieldParameters::Kind::rotating)
    out.require(false, section + "Fiber field/Kind",
                "a rotating fibre field is not its own image in the symmetry face " + face +
                  " (material '" + body.material + "' is anisotropic)",
                "use a constant field, or set the face to free, fixed or roller");
  else if (!in_or_normal)
    out.require(false, section + "Fiber field/Direction",
                "fibres along " + format_point(fibers.direction) +
                  " are not their own image in the symmetry face " + face + " (material '" +
                  body.material + "' is anisotropic); fibres in the face or normal to it are",
                "turn the fibres, or set the face to free, fixed or roller");
}
} // namespace

std::vector<std::string> check_symmetry(const RunParameters& parameters,
                                        const EntryLocator& locator)
{
  const std::vector<mpm::SymmetryPlane> planes = mpm::symmetry_planes(parameters.scene);
  if (planes.empty())
    return {};
  Checker out(locator);
  for (const mpm::SymmetryPlane& plane : planes)
  {
    check_numerics(parameters, plane.face, out);
    for (const mpm::BodyParameters& body : parameters.scene.bodies)
      check_body(parameters.scene, body, plane, out);
  }
  return out.messages;
}
} // namespace vulnus::deck
