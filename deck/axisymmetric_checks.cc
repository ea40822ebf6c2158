// Checks of an axisymmetric deck: what does not turn about the y axis is refused with the
// entry that breaks the symmetry.
#include "deck/axisymmetric_checks.h"

#include "deck/deck_checks.h"
#include "deck/deck_entries.h"
#include "deck/entry_checker.h"
#include "io/mpi_launch.h"
#include "materials/material_registry.h"

#include <cmath>

namespace vulnus::deck
{
namespace
{
using Vector3 = Eigen::Vector3d;

/// Off the axis by more than a millionth of the cell (decks write the axis as exact zeros).
bool off_axis(const Vector3& x, const double cell) { return std::hypot(x[0], x[2]) > 1e-6 * cell; }

void check_method(const RunParameters& p, Checker& out)
{
  if (p.method != Method::mpm)
    out.require(false, "Scene/Method", "a finite element scene is three-dimensional",
            "use Grid/Dimension = 3, or Scene/Method = MPM");
  if (p.hybrid.enabled)
    out.require(false, "Hybrid/Enabled", "the hybrid's far field is a three-dimensional mesh",
            "use Grid/Dimension = 3 for a hybrid, or Hybrid/Enabled = false");
  if (io::launcher_size() > 1)
    out.require(false, "Grid/Dimension", "an axisymmetric run is on one MPI rank (its plane is small)",
            "run it with threads (--threads N) on one rank");
  const mpm::SceneParameters& s = p.scene;
  if (s.shape_function == mpm::ShapeFunction::cpdi)
    out.require(false, "Grid/Shape function",
            "cpdi's domains deform along the hoop direction, across the plane's one cell",
            "use linear or gimp");
  if (s.cell_volume_from_grid_flux)
    out.require(false, "Grid/Volume averaging", "'grid flux' has no hoop face to take a flux through",
            "use cell");
}

void check_domain(const mpm::SceneParameters& s, Checker& out)
{
  const double R = s.domain_max[0], tolerance = 1e-9 * s.cell_size;
  const bool square = std::abs(s.domain_min[0] + R) <= tolerance &&
                      std::abs(s.domain_min[2] + R) <= tolerance &&
                      std::abs(s.domain_max[2] - R) <= tolerance && R > 0.0;
  if (!square)
    out.require(false, "Grid/Domain min",
            "the axis x = z = 0 must be the domain's centre line, with the same range -R..R in "
            "x and z (got " + format_point(s.domain_min) + " to " + format_point(s.domain_max) + ")",
            "set Domain min = -R, y0, -R and Domain max = R, y1, R; the grid then covers the "
            "radius 0..R");
  const mpm::FaceCondition side = s.domain_faces[1];
  for (const int face : {0, 4, 5})
    if (s.domain_faces[face] != side)
    {
      out.require(false, "Grid/Boundary conditions/x+",
              "the four side faces are one surface, r = R, and must have one condition",
              "give x-, x+, z- and z+ the same condition");
      break;
    }
}

void check_body(const mpm::SceneParameters& s, const mpm::BodyParameters& body, Checker& out)
{
  const std::string section = "Body " + body.name + "/";
  switch (body.shape)
  {
    case mpm::BodyShape::box:
      out.require(false, section + "Shape", "a box does not turn about the axis",
              "use a cylinder along y centred on the axis (Shape = cylinder, Axis = 0, 1, 0, "
              "Center = 0, y, 0): a block wide enough that widening it does not change the "
              "answer is a cylinder as well as a box");
      break;
    case mpm::BodyShape::sphere:
      if (off_axis(body.center, s.cell_size))
        out.require(false, section + "Center", "the sphere's centre " + format_point(body.center) + " is off the axis",
                "put it on the axis (x = z = 0), or use Grid/Dimension = 3");
      break;
    case mpm::BodyShape::cylinder:
      if (off_axis(body.center, s.cell_size))
        out.require(false, section + "Center", "the cylinder's centre " + format_point(body.center) + " is off the axis",
                "put it on the axis (x = z = 0), or use Grid/Dimension = 3");
      if (off_axis(body.axis.normalized(), 1.0))
        out.require(false, section + "Axis", "the cylinder's axis " + format_point(body.axis) + " is not along y",
                "use Axis = 0, 1, 0 (or 0, -1, 0), or Grid/Dimension = 3");
      break;
  }
  if (off_axis(body.initial_velocity, 1.0))
    out.require(false, section + "Initial velocity",
            "the velocity " + format_point(body.initial_velocity) + " is not along the axis y",
            "give only its y component; an oblique shot needs Grid/Dimension = 3");
  const mpm::NamedMaterial* material = scene::find_material(s, body.material);
  if (!material)
    return;
  const std::string model = model_subsection(material->parameters.model);
  if (material->parameters.model.find("hyperelastic") != std::string::npos &&
      material->parameters.tissue.failure.regularization_length > 0.0)
    out.require(false, "Material " + body.material + "/" + model + "/Failure/Regularization length",
            "the nonlocal failure average is over three-dimensional neighbourhoods",
            "set it to 0, or use Grid/Dimension = 3");
  if (!materials::create_material(material->parameters)->uses_fibers())
    return;
  const materials::FiberFieldParameters& fibers = body.fibers;
  if (fibers.kind == materials::FiberFieldParameters::Kind::rotating)
    out.require(false, section + "Fiber field/Kind",
            "a rotating fibre field is not symmetric about the axis (material '" +
              body.material + "' is anisotropic)",
            "use Grid/Dimension = 3");
  else if (off_axis(fibers.direction.normalized(), 1e-6))
    out.require(false, section + "Fiber field/Direction",
            "fibres along " + format_point(fibers.direction) +
              " are not symmetric about the axis (material '" + body.material +
              "' is anisotropic); only fibres along y are",
            "use Fiber field/Direction = 0, 1, 0, an isotropic material, or Grid/Dimension = 3");
}
} // namespace

std::vector<std::string> check_axisymmetric(const RunParameters& parameters,
                                            const EntryLocator& locator)
{
  if (!parameters.scene.axisymmetric)
    return {};
  Checker out(locator);
  check_method(parameters, out);
  check_domain(parameters.scene, out);
  for (const mpm::BodyParameters& body : parameters.scene.bodies)
    check_body(parameters.scene, body, out);
  return out.messages;
}
} // namespace vulnus::deck
