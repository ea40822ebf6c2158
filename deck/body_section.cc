// Deck subsections `Body <name>`: geometry, material, density, initial velocity, particle
// density, rigid motion and fiber field of each body. Bodies named `slab` and `bullet`
// default to the paper's reference scene (docs/DESIGN.md section 2).
#include "deck/deck_sections.h"

namespace vulnus::deck
{
namespace
{
using namespace dealii;

/// The paper's reference scene: the slab spans y in [0, 10] mm, the bullet's nose starts
/// 1 mm before the entrance face and it travels along +y.
mpm::BodyParameters default_body(const std::string& name)
{
  mpm::BodyParameters body;
  body.name = name;
  if (name == "slab")
  {
    body.material = "tissue";
    body.shape = mpm::BodyShape::box;
    body.box_min = Eigen::Vector3d(-0.025, 0.0, -0.025);
    body.box_max = Eigen::Vector3d(0.025, 0.01, 0.025);
    body.density = 1060.0;
    body.fibers.kind = materials::FiberFieldParameters::Kind::rotating;
    body.fibers.direction = Eigen::Vector3d::UnitX();
    body.fibers.axis = Eigen::Vector3d::UnitY();
    body.fibers.start_coordinate = 0.0;
    body.fibers.end_coordinate = 0.01;
    body.fibers.total_angle_degrees = 180.0;
  }
  else if (name == "bullet")
  {
    body.material = "bullet";
    body.shape = mpm::BodyShape::cylinder;
    body.center = Eigen::Vector3d(0.0, -0.016, 0.0);
    body.radius = 0.0045;
    body.length = 0.015;
    body.axis = Eigen::Vector3d::UnitY();
    body.nose = mpm::NoseShape::hemispherical;
    body.density = 8930.0;
    body.initial_velocity = Eigen::Vector3d(0.0, 150.0, 0.0);
    body.is_projectile = true;
  }
  return body;
}

const char* shape_names[3] = {"box", "cylinder", "sphere"};
} // namespace

void declare_body_sections(EntryTable& table, const std::vector<std::string>& names)
{
  for (const std::string& name : names)
  {
    const mpm::BodyParameters d = default_body(name);
    table.enter("Body " + name);
    table.declare("Material", d.material, Patterns::Anything(),
                  "Name of the body's material, one of Scene/Materials.");
    table.declare("Shape", shape_names[static_cast<int>(d.shape)],
                  Patterns::Selection("box|cylinder|sphere"),
                  "Geometry: box (Box min, Box max), cylinder (a bullet: Center of the tail "
                  "face, Radius, Length, Axis, Nose) or sphere (Center, Radius).");
    table.declare("Box min", format_point(d.box_min), point_pattern(),
                  "Box: lower corner `x, y, z` [m].");
    table.declare("Box max", format_point(d.box_max), point_pattern(),
                  "Box: upper corner `x, y, z` [m].");
    table.declare("Center", format_point(d.center), point_pattern(),
                  "Sphere: centre; cylinder: centre of the tail face, `x, y, z` [m].");
    table.declare("Radius", format_number(d.radius), Patterns::Double(0.0),
                  "Sphere or cylinder radius r [m] (the paper's bullet: 4.5 mm).");
    table.declare("Length", format_number(d.length), Patterns::Double(0.0),
                  "Cylinder overall length L including the nose [m] (default bullet: 15 mm).");
    table.declare("Axis", format_point(d.axis), point_pattern(),
                  "Cylinder axis from tail to nose, `x, y, z` (normalized) [-].");
    table.declare("Nose", d.nose == mpm::NoseShape::flat ? "flat" : "hemispherical",
                  Patterns::Selection("flat|hemispherical"), "Cylinder nose shape.");
    table.declare("Density", format_number(d.density), Patterns::Double(0.0),
                  "Mass density rho [kg/m^3]; > 0 (tissue 1060, bullet 8930).");
    table.declare("Initial velocity", format_point(d.initial_velocity), point_pattern(),
                  "Initial velocity v0, `x, y, z` [m/s] (the paper: 150 or 50 m/s).");
    table.declare("Particles per cell", std::to_string(d.particles_per_cell),
                  Patterns::Integer(1, 16),
                  "Material points per grid cell along each axis (the paper: 4).");
    table.declare("Rigid motion", d.rigid_motion == mpm::RigidMotion::free ? "free" : "prescribed",
                  Patterns::Selection("prescribed|free"),
                  "For a rigid material: prescribed (keeps its initial velocity) or free "
                  "(driven by the contact force).");
    table.declare("Projectile", d.is_projectile ? "true" : "false", Patterns::Bool(),
                  "This body is the projectile whose position, velocity and contact force the "
                  "history reports (at most one).");
    table.enter("Fiber field");
    table.declare("Kind",
                  d.fibers.kind == materials::FiberFieldParameters::Kind::rotating ? "rotating"
                                                                                   : "constant",
                  Patterns::Selection("constant|rotating"),
                  "Reference fiber direction a0: constant, or rotating about Axis from Start to "
                  "End (used when the material has fibers).");
    table.declare("Direction", format_point(d.fibers.direction), point_pattern(),
                  "Fiber direction a0 (at the start face when rotating), `x, y, z` [-].");
    table.declare("Axis", format_point(d.fibers.axis), point_pattern(),
                  "Rotation axis (through the thickness), `x, y, z` [-].");
    table.declare("Start", format_number(d.fibers.start_coordinate), Patterns::Double(),
                  "Coordinate along Axis of the face where the rotation starts [m].");
    table.declare("End", format_number(d.fibers.end_coordinate), Patterns::Double(),
                  "Coordinate along Axis of the face where the rotation ends [m].");
    table.declare("Angle", format_number(d.fibers.total_angle_degrees), Patterns::Double(),
                  "Total rotation from Start to End [degrees], clockwise seen along +Axis (the "
                  "paper: 180).");
    table.leave();
    table.leave();
  }
}

std::vector<mpm::BodyParameters> parse_body_sections(ParameterHandler& prm,
                                                     const std::vector<std::string>& names)
{
  std::vector<mpm::BodyParameters> bodies;
  for (const std::string& name : names)
  {
    prm.enter_subsection("Body " + name);
    mpm::BodyParameters body;
    body.name = name;
    body.material = prm.get("Material");
    const std::string shape = prm.get("Shape");
    body.shape = shape == "cylinder" ? mpm::BodyShape::cylinder
                 : shape == "sphere" ? mpm::BodyShape::sphere
                                     : mpm::BodyShape::box;
    body.box_min = get_point(prm, "Box min");
    body.box_max = get_point(prm, "Box max");
    body.center = get_point(prm, "Center");
    body.radius = prm.get_double("Radius");
    body.length = prm.get_double("Length");
    body.axis = get_point(prm, "Axis");
    body.nose = prm.get("Nose") == "flat" ? mpm::NoseShape::flat : mpm::NoseShape::hemispherical;
    body.density = prm.get_double("Density");
    body.initial_velocity = get_point(prm, "Initial velocity");
    body.particles_per_cell = static_cast<unsigned int>(prm.get_integer("Particles per cell"));
    body.rigid_motion =
        prm.get("Rigid motion") == "free" ? mpm::RigidMotion::free : mpm::RigidMotion::prescribed;
    body.is_projectile = prm.get_bool("Projectile");
    prm.enter_subsection("Fiber field");
    body.fibers.kind = prm.get("Kind") == "rotating"
                           ? materials::FiberFieldParameters::Kind::rotating
                           : materials::FiberFieldParameters::Kind::constant;
    body.fibers.direction = get_point(prm, "Direction");
    body.fibers.axis = get_point(prm, "Axis");
    body.fibers.start_coordinate = prm.get_double("Start");
    body.fibers.end_coordinate = prm.get_double("End");
    body.fibers.total_angle_degrees = prm.get_double("Angle");
    prm.leave_subsection();
    prm.leave_subsection();
    bodies.push_back(body);
  }
  return bodies;
}
} // namespace vulnus::deck
