// Deck section `Grid`: the MPM background grid, shape functions, update scheme and the
// boundary conditions on the faces of the grid domain.
#include "deck/deck_sections.h"

namespace vulnus::deck
{
namespace
{
mpm::FaceCondition face_condition(const std::string& text)
{
  if (text == "fixed")
    return mpm::FaceCondition::fixed;
  if (text == "roller")
    return mpm::FaceCondition::roller;
  if (text == "symmetry")
    return mpm::FaceCondition::symmetry;
  return mpm::FaceCondition::free;
}
} // namespace

void declare_grid_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Grid");
  table.declare("Domain min", "-0.025, -0.02, -0.025", point_pattern(),
                "Lower corner x_min of the background grid domain, `x, y, z` [m]. The default "
                "puts the x and z faces on the slab's side faces.");
  table.declare("Domain max", "0.025, 0.03, 0.025", point_pattern(),
                "Upper corner x_max of the background grid domain, `x, y, z` [m].");
  table.declare("Dimension", "3", Patterns::Selection("3|axisymmetric"),
                "3 (the bodies in space) or axisymmetric (a scene that turns about the y axis, "
                "x = z = 0, solved in its r-y half plane: about 100 times fewer points at the "
                "same cell; docs/axisymmetric.md). Axisymmetric needs bodies of revolution "
                "about that axis (spheres and cylinders centred on it, the cylinders along y), "
                "velocities along y, isotropic materials or fibres along y, a domain "
                "whose x and z ranges are the same -R..R (the grid covers r from 0 to R), and "
                "one condition on the four side faces (the surface r = R).");
  table.declare("Cell size", "0.001", Patterns::Double(0.0),
                "Edge length h of the cubic grid cells [m]; must be > 0. The paper uses 1 mm.");
  table.declare("Shape function", "linear", Patterns::Selection("linear|gimp|cpdi"),
                "Grid shape functions: linear (tent), gimp (uGIMP: a fixed box per point) or "
                "cpdi (CPDI1: a parallelepiped per point that deforms with its F, for tissue "
                "stretched beyond the point spacing; a domain reaching over a cell from its "
                "point along an axis is shrunk to it).");
  table.declare("Update scheme", "MUSL", Patterns::Selection("USL|MUSL"),
                "Stress update: USL (update stress last) or MUSL (modified USL, velocities "
                "re-mapped to the grid before the stress update).");
  table.declare("Velocity transfer", "FLIP",
                Patterns::Selection("relaxed PIC|relaxed APIC|APIC|FLIP|PIC|XPIC|FMPM"),
                "How points take their velocity from the grid: relaxed PIC (FLIP increments "
                "relaxed towards the PIC velocity over the time in Velocity relaxation, a rate "
                "fixed in time so the answer does not depend on the step count; hybrid runs "
                "use FLIP, which the interface exchange assumes), relaxed APIC (the same "
                "towards APIC), APIC (affine particle-in-cell, "
                "Jiang et al. 2015: PIC plus the velocity gradient at the point, which keeps "
                "rotation and shear without FLIP's noise), FLIP (velocity increments; no "
                "damping, overshoots where contact changes a node's velocity), PIC (damps "
                "every mode the grid cannot hold) or XPIC (Hammerquist and Nairn 2017: PIC plus "
                "the part of the points' velocities that a grid field fits, from XPIC order "
                "terms of a series, so a rigid rotation or any motion the grid resolves passes "
                "undamped while FLIP's noise is removed; pure MPM only) or FMPM (Nairn and "
                "Hammerquist 2021: PIC from the new grid velocities that the consistent mass "
                "matrix gives, its inverse approximated by FMPM order terms of the same series; "
                "no FLIP increments are carried, and each term is one more pass over the points; "
                "pure MPM only).");
  table.declare("XPIC order", "5", Patterns::Integer(1, 20),
                "XPIC: the number m of terms of its series (1 is PIC; each further term is one "
                "more pass over the points) [-].");
  table.declare("FMPM order", "5", Patterns::Integer(1, 20),
                "FMPM: the number m of terms of the consistent mass matrix's series (1 is PIC; "
                "each further term is one more pass over the points) [-].");
  table.declare("Velocity relaxation", "1", Patterns::Double(1e-3, 1e3),
                "relaxed PIC and APIC: relaxation time tau of the FLIP part in Courant times h / max(c + "
                "|v|) (the step at CFL 1) [-]; the FLIP fraction per step is exp(-dt / tau).");
  table.declare("Projectile velocity relaxation", "0.1", Patterns::Double(0.0, 1e3),
                "A deformable projectile's points relax their FLIP velocity towards the PIC "
                "velocity over this many of the projectile's own Courant times h / max(c + |v|) "
                "[-] (0: the projectile uses Velocity transfer like every body). Each contact "
                "impulse sets a stiff projectile's surface ringing at its grid frequency; FLIP "
                "never damps it and the metal yields numerically (docs/converged_wound.md). "
                "The energy taken is booked as dissipated.");
  table.declare("Deformation update", "midpoint", Patterns::Selection("midpoint|forward Euler"),
                "Update of the deformation gradient over a step with velocity gradient L: "
                "midpoint F <- (I - dt L/2)^-1 (I + dt L/2) F (second order, exact for rigid "
                "spin) or forward Euler F <- (I + dt L) F (first order: a spinning point "
                "stretches by (1 + (w dt)^2)^(1/2) per step).");
  table.declare("Volume averaging", "none", Patterns::Selection("none|cell|grid flux"),
                "Volumetric part of the points' deformation: none (each point its own J), "
                "cell (F-bar: each step's volume change of a point is that of all the points of "
                "its body in its cell, Coombs et al. 2018) or grid flux (as cell, with the "
                "cell's volume change taken from the grid velocity's flux through its faces, so "
                "that a confined body's points keep its cells' volume). cell and grid flux "
                "remove the volumetric locking of nearly incompressible tissue (bulk:shear 1e3 "
                "and more, water-stiff tissue and gelatin); docs/locking.md.");
  table.declare("Points leaving the grid", "stop", Patterns::Selection("stop|remove"),
                "stop: a point leaving the grid ends the run as a blow-up (last good state "
                "kept); remove: it is removed and its energy and momentum booked as outflow "
                "(fragments flying off the exit face).");
  table.declare("Point splitting", "0", Patterns::Double(0.0, 8.0),
                "A deformable body's point splits in two, each half of it, once an edge of its "
                "domain (a cube of its volume at seeding, deformed with the material since) is "
                "longer than this many cells [cells]; 0 (the default): never. In 3D, tissue "
                "flowing around a projectile is drawn apart along the hoop direction too, and "
                "two points per cell axis then sample it too coarsely; 0.75 splits points "
                "seeded 2 per cell axis where the material stretched by half "
                "(docs/point_splitting.md). 3D grid, linear shape functions; above every "
                "deformable body's seeding (1 / Particles per cell).");
  table.enter("Grading");
  table.declare("Largest cell", "1", Patterns::Double(1.0, 64.0),
                "The widest cell of a graded grid, in cells of Cell size [-]; 1 (the default) "
                "is a uniform grid. Cells are Cell size h inside the fine box and h min(Largest "
                "cell, 1 + d / Growth length) at a distance d outside it, along each axis; "
                "halving h halves every cell; the cells at the domain's faces are widened or "
                "cut to end on them. Pure MPM on one MPI rank, linear shape functions, "
                "Volume averaging none or cell, no nonlocal failure (docs/graded_grid.md).");
  table.declare("Growth length", "0.002", Patterns::Double(0.0),
                "Distance from the fine box over which a graded grid's cells double [m]; > 0.");
  table.declare("Fine box min", "0, 0, 0", point_pattern(),
                "Lower corner of the box of h-wide cells, `x, y, z` [m]; in an axisymmetric "
                "scene its x and z are -R_f (the fine radius R_f).");
  table.declare("Fine box max", "0, 0, 0", point_pattern(),
                "Upper corner of the box of h-wide cells, `x, y, z` [m]; it must hold the "
                "projectile's path and the wound around it.");
  table.leave();
  table.enter("Boundary conditions");
  for (unsigned int face = 0; face < 6; ++face)
  {
    const bool side = face < 2 || face > 3;
    table.declare(scene::face_name(face), side ? "fixed" : "free",
                  Patterns::Selection("free|fixed|roller|symmetry"),
                  std::string("Condition on the domain face ") + scene::face_name(face) +
                      ": free, fixed (zero velocity), roller (zero normal velocity) or symmetry "
                      "(a mirror plane of the scene: zero normal velocity, and bodies may cross "
                      "it, their part inside the domain modelled; docs/symmetry.md). The paper "
                      "fixes the x and z faces and leaves the y faces free.");
  }
  table.leave();
  table.leave();
}

void parse_grid_section(dealii::ParameterHandler& prm, mpm::SceneParameters& scene)
{
  prm.enter_subsection("Grid");
  scene.domain_min = get_point(prm, "Domain min");
  scene.domain_max = get_point(prm, "Domain max");
  scene.cell_size = prm.get_double("Cell size");
  scene.axisymmetric = prm.get("Dimension") == "axisymmetric";
  prm.enter_subsection("Grading");
  scene.grading.largest_cells = prm.get_double("Largest cell");
  scene.grading.growth_length = prm.get_double("Growth length");
  const Eigen::Vector3d fine_min = get_point(prm, "Fine box min");
  const Eigen::Vector3d fine_max = get_point(prm, "Fine box max");
  for (int d = 0; d < 3; ++d)
  {
    scene.grading.fine_min[d] = fine_min[d];
    scene.grading.fine_max[d] = fine_max[d];
  }
  prm.leave_subsection();
  const std::string shape = prm.get("Shape function");
  scene.shape_function = shape == "gimp"   ? mpm::ShapeFunction::gimp
                         : shape == "cpdi" ? mpm::ShapeFunction::cpdi
                                           : mpm::ShapeFunction::linear;
  scene.update_scheme =
      prm.get("Update scheme") == "USL" ? mpm::UpdateScheme::usl : mpm::UpdateScheme::musl;
  const std::string transfer = prm.get("Velocity transfer");
  scene.velocity_transfer = transfer == "FLIP"   ? mpm::VelocityTransfer::flip
                            : transfer == "PIC"  ? mpm::VelocityTransfer::pic
                            : transfer == "APIC" ? mpm::VelocityTransfer::apic
                            : transfer == "XPIC" ? mpm::VelocityTransfer::xpic
                            : transfer == "FMPM" ? mpm::VelocityTransfer::fmpm
                            : transfer == "relaxed PIC" ? mpm::VelocityTransfer::relaxed_pic
                                                 : mpm::VelocityTransfer::relaxed_apic;
  scene.velocity_relaxation = prm.get_double("Velocity relaxation");
  scene.series_order = static_cast<int>(
      prm.get_integer(scene.velocity_transfer == mpm::VelocityTransfer::fmpm ? "FMPM order"
                                                                             : "XPIC order"));
  scene.projectile_velocity_relaxation = prm.get_double("Projectile velocity relaxation");
  scene.deformation_update = prm.get("Deformation update") == "forward Euler"
                                 ? mpm::DeformationUpdate::forward_euler
                                 : mpm::DeformationUpdate::midpoint;
  const std::string averaging = prm.get("Volume averaging");
  scene.cell_volume_averaging = averaging != "none";
  scene.cell_volume_from_grid_flux = averaging == "grid flux";
  scene.remove_points_leaving_grid = prm.get("Points leaving the grid") == "remove";
  scene.point_split_edge_cells = prm.get_double("Point splitting");
  prm.enter_subsection("Boundary conditions");
  for (unsigned int face = 0; face < 6; ++face)
    scene.domain_faces[face] = face_condition(prm.get(scene::face_name(face)));
  prm.leave_subsection();
  prm.leave_subsection();
}
} // namespace vulnus::deck
