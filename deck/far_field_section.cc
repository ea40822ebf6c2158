// Deck section `Far field`: the numerics of the finite element region (time integrator, mesh
// grading, Newton and Krylov settings) and an optional face load for pure-FE scenes; and the
// entry Scene/Method that selects a pure-FE scene.
#include "deck/deck_sections.h"

#include <array>

namespace vulnus::deck
{
namespace
{
const std::array<const char*, 6> face_names{{"x-", "x+", "y-", "y+", "z-", "z+"}};
}

void declare_far_field_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Far field");
  table.declare("Integrator", "central difference",
                Patterns::Selection("central difference|Newmark|generalized alpha"),
                "Time integration of the FE region: explicit central difference (lumped mass, "
                "CFL step), implicit Newmark average acceleration, or generalized alpha.");
  table.declare("Element degree", "1", Patterns::Integer(1, 2),
                "Degree of the Lagrange elements (Q1 or Q2); a hybrid scene needs 1.");
  table.declare("Volume averaging", "none", Patterns::Selection("none|cell"),
                "Volumetric part of the elements' deformation: none (each quadrature point its "
                "own J) or cell (F-bar with the cell's mean J, de Souza Neto et al. 1996): cell "
                "removes the volumetric locking of nearly incompressible tissue (bulk:shear 1e3 "
                "and more); docs/locking.md.");
  table.declare("Integration", "automatic", Patterns::Selection("automatic|full|one point"),
                "Points per cell where the law is evaluated: full (2 x 2 x 2 Gauss points for "
                "Q1), one point (the cell's mean gradient, with hourglass forces of the full "
                "element's deviatoric stiffness; explicit Q1 only, about a third of the full "
                "cells' cost), or automatic: one point for the explicit Q1 far field, full "
                "otherwise; docs/far_field.md section 10.");
  table.declare("Hourglass coefficient", "1", Patterns::Double(0.0, 10.0),
                "One-point integration: scale of the hourglass stiffness, in (0, 10]; 1 is the "
                "full element's response to the hourglass modes at small strain.");
  table.declare("Shock viscosity", "false", Patterns::Bool(),
                "Explicit far field: true gives its cells the bulk viscosity of Time/Artificial "
                "viscosity linear and quadratic, with h the cell's size, as the MPM points have "
                "it (for shocks that reach the far field). false (default): none; the far "
                "field carries elastic waves, and the linear term damps the target's ringing "
                "by an amount of order h that a refined run does not have (docs/far_field.md "
                "section 11). The implicit integrators have none (their damping is the "
                "spectral radius) and refuse true.");
  table.declare("CFL", "0.5", Patterns::Double(0.0, 1.0),
                "Explicit: Courant number in dt = CFL h_min / c over the cells, in (0, 1].");
  table.declare("Time step", "1e-5", Patterns::Double(0.0),
                "Implicit: the time step [s] (chosen for accuracy; the multi-step hybrid "
                "scheme takes it as the FE window), > 0.");
  table.declare("Spectral radius", "0.8", Patterns::Double(0.0, 1.0),
                "Generalized alpha: spectral radius rho_inf at infinite frequency in [0, 1] "
                "(1: no numerical damping, 0: strongest).");
  table.declare("Far cell size", "0.004", Patterns::Double(0.0),
                "Largest cell size far from the MPM zone [m]; the mesh grows from the grid "
                "spacing at the interface (or is uniform at Grid/Cell size without a zone).");
  table.declare("Grading ratio", "1.3", Patterns::Double(1.0),
                "Size ratio of neighbouring cells growing away from the zone, >= 1.");
  table.declare("Supported face cells", "2", Patterns::Double(0.0),
                "Width of the cells at a fixed or roller slab face, in grid cells (>= 1): the "
                "graded cells shrink back to it towards such a face, so that its reaction is "
                "resolved; 0: the cells grow on to the face.");
  table.declare("Newton tolerance", "1e-8", Patterns::Double(0.0, 1.0),
                "Implicit: relative residual tolerance of Newton's method.");
  table.declare("Maximum Newton iterations", "25", Patterns::Integer(1, 1000),
                "Implicit: Newton iterations before the step is declared failed.");
  table.declare("Linear solver", "cg", Patterns::Selection("cg|gmres|direct"),
                "Implicit: solver of the Newton systems: a Krylov solver (cg, gmres) with an "
                "algebraic multigrid preconditioner, or direct (sparse LU by MUMPS, one "
                "factorization per Newton correction; its memory grows faster than the dofs).");
  table.declare("Linear tolerance", "1e-10", Patterns::Double(0.0, 1.0),
                "Implicit: relative tolerance of the Krylov solver.");
  table.declare("Maximum linear iterations", "2000", Patterns::Integer(1, 1000000),
                "Implicit: Krylov iterations before the solve is declared failed.");
  table.declare("Reuse preconditioner", "true", Patterns::Bool(),
                "Implicit: keep the multigrid hierarchy between Newton solves while the step "
                "length holds and the Krylov iterations stay below twice (+10) those after "
                "its set-up; false rebuilds it for every solve.");
  table.declare("Interface stiffness solver", "automatic",
                Patterns::Selection("automatic|direct|iterative"),
                "Implicit hybrid: how the window's effective interface mass is probed. direct: "
                "one sparse LU factorization (MUMPS) of the held Newton matrix serves every "
                "probe; iterative: a multigrid-preconditioned CG solve per probe; automatic: "
                "direct up to 150,000 far-field dofs (docs/far_field.md section 8).");
  table.declare("Load face", "none", Patterns::Selection("none|x-|x+|y-|y+|z-|z+"),
                "Pure-FE scenes: a slab face carrying a prescribed velocity or traction.");
  table.declare("Load kind", "velocity", Patterns::Selection("velocity|traction"),
                "velocity: all components prescribed [m/s]; traction: nominal dead load [Pa].");
  table.declare("Load value", "0, 0, 0", point_pattern(), "Load vector, times the profile.");
  table.declare("Load profile", "constant",
                Patterns::Selection("constant|ramp|half sine|sine squared"),
                "Time factor g(t): 1; min(t/T, 1); sin(pi t/T) then 0; sin^2(pi t/T) then 0.");
  table.declare("Load duration", "1e-4", Patterns::Double(0.0),
                "T of the load profile [s], > 0 unless the profile is constant.");
  table.leave();
}

void parse_far_field_section(dealii::ParameterHandler& prm, RunParameters& parameters)
{
  prm.enter_subsection("Scene");
  parameters.method = prm.get("Method") == "FE" ? Method::fe : Method::mpm;
  prm.leave_subsection();

  fem::FeSceneParameters& f = parameters.far_field;
  prm.enter_subsection("Far field");
  const std::string integrator = prm.get("Integrator");
  f.integrator = integrator == "Newmark"             ? fem::TimeIntegrator::newmark
                 : integrator == "generalized alpha" ? fem::TimeIntegrator::generalized_alpha
                                                     : fem::TimeIntegrator::central_difference;
  f.degree = static_cast<unsigned int>(prm.get_integer("Element degree"));
  f.volume_averaging = prm.get("Volume averaging") == "cell";
  const std::string integration = prm.get("Integration");
  f.one_point_integration =
    integration == "one point" ||
    (integration == "automatic" && f.integrator == fem::TimeIntegrator::central_difference &&
     f.degree == 1);
  f.hourglass_coefficient = prm.get_double("Hourglass coefficient");
  if (prm.get_bool("Shock viscosity")) // an implicit far field refuses it (fem::check_parameters)
    f.shock_viscosity = {parameters.scene.artificial_viscosity_linear,
                         parameters.scene.artificial_viscosity_quadratic};
  f.cfl = prm.get_double("CFL");
  f.time_step = prm.get_double("Time step");
  f.spectral_radius = prm.get_double("Spectral radius");
  f.far_cell_size = prm.get_double("Far cell size");
  f.grading_ratio = prm.get_double("Grading ratio");
  f.supported_face_cells = prm.get_double("Supported face cells");
  f.newton_relative_tolerance = prm.get_double("Newton tolerance");
  f.max_newton_iterations = static_cast<unsigned int>(prm.get_integer("Maximum Newton iterations"));
  const std::string linear_solver = prm.get("Linear solver");
  f.linear_solver = linear_solver == "gmres"    ? fem::LinearSolverType::gmres
                    : linear_solver == "direct" ? fem::LinearSolverType::direct
                                                : fem::LinearSolverType::cg;
  f.linear_relative_tolerance = prm.get_double("Linear tolerance");
  f.reuse_preconditioner = prm.get_bool("Reuse preconditioner");
  const std::string stiffness_solver = prm.get("Interface stiffness solver");
  f.interface_stiffness_solver = stiffness_solver == "direct"
                                   ? fem::InterfaceStiffnessSolver::direct
                                 : stiffness_solver == "iterative"
                                   ? fem::InterfaceStiffnessSolver::iterative
                                   : fem::InterfaceStiffnessSolver::automatic;
  f.max_linear_iterations =
    static_cast<unsigned int>(prm.get_integer("Maximum linear iterations"));
  const std::string face = prm.get("Load face");
  for (unsigned int i = 0; i < face_names.size(); ++i)
    if (face == face_names[i])
    {
      fem::FaceParameters& load = f.faces[i];
      load.condition = prm.get("Load kind") == "traction"
                         ? fem::FaceParameters::Condition::traction
                         : fem::FaceParameters::Condition::velocity;
      const Eigen::Vector3d value = get_point(prm, "Load value");
      load.value = {value[0], value[1], value[2]};
      const std::string profile = prm.get("Load profile");
      load.profile.kind = profile == "ramp"           ? fem::TimeProfile::Kind::ramp
                          : profile == "half sine"    ? fem::TimeProfile::Kind::half_sine
                          : profile == "sine squared" ? fem::TimeProfile::Kind::sine_squared
                                                      : fem::TimeProfile::Kind::constant;
      load.profile.duration = prm.get_double("Load duration");
    }
  prm.leave_subsection();
}
} // namespace vulnus::deck
