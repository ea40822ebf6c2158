// Plain parameter structs of the finite element far field (docs/DESIGN.md section 5): mesh of the
// slab minus the MPM zone, element, time integrator, Newton and Krylov settings, face
// conditions, material and output. Filled by the deck reader (app/) or by tests. SI units.
#pragma once

#include "core/parameter_problem.h"

#include "materials/fiber_field.h"
#include "materials/material_parameters.h"
#include "materials/shock_viscosity.h"

#include <array>
#include <string>
#include <vector>

namespace vulnus::fem
{
/// Scalar time factor g(t) that multiplies a prescribed face velocity or traction.
///   constant        g = 1
///   ramp            g = min(t / duration, 1)
///   half_sine       g = sin(pi t / duration) for t < duration, else 0
///   sine_squared    g = sin^2(pi t / duration) for t < duration, else 0 (C1 pulse)
struct TimeProfile
{
  enum class Kind
  {
    constant,
    ramp,
    half_sine,
    sine_squared
  };
  Kind kind = Kind::constant;
  double duration = 0.0; ///< s, > 0 for every kind but constant

  double value(double time) const;
};

/// Condition of one slab face.
///   free      no constraint, no load
///   fixed     all velocity components zero
///   roller    normal velocity component zero, tangential free
///   velocity  all velocity components prescribed: value * g(t) (m/s)
///   traction  nominal (reference-area) dead traction value * g(t) (Pa)
struct FaceParameters
{
  enum class Condition
  {
    free,
    fixed,
    roller,
    velocity,
    traction
  };
  Condition condition = Condition::free;
  std::array<double, 3> value{{0.0, 0.0, 0.0}};
  TimeProfile profile;
};

/// What the coupling does on the surface of the hole (the MPM zone).
///   free            traction free (pure FE scene)
///   velocity_driven the interface velocities are Dirichlet values set by the caller
enum class InterfaceCondition
{
  free,
  velocity_driven
};

enum class TimeIntegrator
{
  central_difference, ///< explicit, lumped mass, CFL step
  newmark,            ///< implicit average acceleration (beta = 1/4, gamma = 1/2)
  generalized_alpha   ///< implicit Chung-Hulbert 1993 with spectral radius rho_inf
};

/// How the implicit interface stiffness's probing solves are done: one sparse direct
/// factorization of the held Newton matrix serving every probe, or a multigrid-preconditioned
/// CG solve per probe; automatic takes the direct one up to 150,000 far-field dofs.
enum class InterfaceStiffnessSolver
{
  automatic,
  direct,
  iterative
};

enum class LinearSolverType
{
  cg,
  gmres,
  direct ///< sparse LU (MUMPS), factorized for every Newton correction
};

/// Face order of FeSceneParameters::faces and of the boundary ids: x-, x+, y-, y+, z-, z+.
inline constexpr unsigned int n_slab_faces = 6;

/// What a far-field cell's failure proximity (the adaptive zone's criterion) measures.
enum class FailureProximity
{
  any_failure,  ///< the nearest failure of matrix or fibres
  total_failure ///< the nearest failure of both
};

struct FeSceneParameters
{
  /// Slab box (m). The paper's slab: 50 x 10 x 50 mm, y through the thickness.
  std::array<double, 3> slab_min{{0.0, 0.0, 0.0}};
  std::array<double, 3> slab_max{{0.05, 0.01, 0.05}};

  /// Optional box-shaped hole (the MPM zone), aligned with the interface cell size; may touch
  /// slab faces (e.g. through the whole thickness).
  bool has_hole = false;
  std::array<double, 3> hole_min{{0.02, 0.0, 0.02}};
  std::array<double, 3> hole_max{{0.03, 0.01, 0.03}};
  /// Optional box meshed with cells of the interface cell size, holding the hole (the region
  /// an adaptive MPM zone may grow into): the cells there stay the same when the hole grows
  /// inside it. Without it the fine cells are the hole's own extent.
  bool has_focus = false;
  /// Keep, per cell, how near its points are to failure (the adaptive zone's criterion,
  /// FarFieldSolver::cells_nearing_failure), evaluated with every force evaluation.
  bool track_failure_proximity = false;
  /// What that proximity measures: the nearest failure of any part (a point that has failed
  /// at all is infinitely near), or the nearest total failure, so that the far field carries
  /// matrix failure: a point is as near as the later of its matrix and its fibres, a failed
  /// part counting as past its limit.
  FailureProximity failure_proximity = FailureProximity::any_failure;
  /// The explicit force evaluation skips cells still at rest (no node moved more than 1e-12
  /// of the cell size, every point intact): their force is zero to that strain. Off only to
  /// check that skipping changes nothing.
  bool skip_quiet_cells = true;
  std::array<double, 3> focus_min{{0.0, 0.0, 0.0}};
  std::array<double, 3> focus_max{{0.0, 0.0, 0.0}};

  /// Cell size next to the hole (the MPM grid spacing), m. Without a hole the mesh is uniform
  /// with about this size.
  double interface_cell_size = 1.0e-3;
  /// Largest cell size far from the hole, m (>= interface_cell_size).
  double far_cell_size = 4.0e-3;
  /// Ratio of the sizes of neighbouring cells away from the hole, >= 1.
  double grading_ratio = 1.3;
  /// Width of the cells next to a fixed or roller slab face, in interface cells: the grading
  /// shrinks back to it toward such a face, so that the face's reaction is resolved
  /// (docs/far_field.md section 2). 0: the cells grow on to the face.
  double supported_face_cells = 0.0;
  /// Uniform refinements of the graded mesh (convergence studies; creates no hanging nodes).
  unsigned int n_global_refinements = 0;

  unsigned int degree = 1; ///< 1 (Q1) or 2 (Q2)
  /// The law sees F_bar = (J_bar / J)^(1/3) F with the cell's mean J (fem/volume_averaged_cell.h):
  /// no volumetric locking of nearly incompressible tissue.
  bool volume_averaging = false;
  /// Explicit Q1 only: the law at one point per cell (its centre) and hourglass forces for the
  /// modes one point does not see (fem/hourglass.h); false: (degree + 1)^3 Gauss points.
  bool one_point_integration = false;
  /// Scale of the hourglass stiffness: 1 gives the eight-point F-bar element's response to
  /// the hourglass modes for small strains of an isotropic law (exactly, on box cells).
  double hourglass_coefficient = 1.0;
  /// Explicit only: the bulk viscosity of the MPM points (materials/shock_viscosity.h) in the
  /// cells, h the cell's size; refused with an implicit integrator. Off by default.
  materials::ShockViscosity shock_viscosity;

  TimeIntegrator integrator = TimeIntegrator::central_difference;
  double cfl = 0.5;             ///< explicit: dt = cfl * min over cells h / c
  /// Explicit only: keep velocities at half steps as the MPM side does (symplectic Euler,
  /// v_{n+1/2} = v_{n-1/2} + dt M^{-1} f(u_n), u_{n+1} = u_n + dt v_{n+1/2}); a
  /// velocity-driven interface then moves with its target over the step. Used by the
  /// coupling; the default is the velocity-Verlet form with full-step velocities.
  bool staggered_velocity = false;
  double time_step = 1.0e-5;    ///< implicit, s
  double spectral_radius = 0.8; ///< generalized-alpha rho_inf in [0, 1]
  unsigned int max_newton_iterations = 25;
  /// Newton converges when |r| <= relative tolerance * max(|r_0|, |f_int|) (|f_int| alone in
  /// the first iteration), or |r| <= absolute tolerance, or the last correction |du| <=
  /// max(relative tolerance, 1e-10) * |u_{n+1} - u_n| or <= 1e-12 * interface cell size *
  /// sqrt(n dofs) with |r| <= |r_0| / 10 (a far field at rest: strains at round-off), or the
  /// residual stops falling
  /// (|r_k| > |r_{k-1}| / 2, k >= 2) below 1e-4 of the force scale (round-off floor).
  double newton_relative_tolerance = 1.0e-8;
  double newton_absolute_tolerance = 0.0; ///< N; 0: relative test only
  LinearSolverType linear_solver = LinearSolverType::cg;
  double linear_relative_tolerance = 1.0e-10;
  unsigned int max_linear_iterations = 2000;
  /// Keep the algebraic multigrid hierarchy from one Newton solve to the next (within a
  /// step and across steps) while the step length holds and the Krylov iterations stay below
  /// twice, plus 10, those of the first solve after it was built; false: rebuild every solve.
  bool reuse_preconditioner = true;
  InterfaceStiffnessSolver interface_stiffness_solver = InterfaceStiffnessSolver::automatic;

  /// Paper default: the four side faces (normals x and z) fixed, entrance and exit free.
  std::array<FaceParameters, n_slab_faces> faces{{{FaceParameters::Condition::fixed, {}, {}},
                                                  {FaceParameters::Condition::fixed, {}, {}},
                                                  {FaceParameters::Condition::free, {}, {}},
                                                  {FaceParameters::Condition::free, {}, {}},
                                                  {FaceParameters::Condition::fixed, {}, {}},
                                                  {FaceParameters::Condition::fixed, {}, {}}}};
  InterfaceCondition interface_condition = InterfaceCondition::free;

  materials::MaterialParameters material;
  double density = 1060.0; ///< kg/m^3, reference density
  materials::FiberFieldParameters fibers;

  double end_time = 1.0e-3; ///< s
};

/// Problems with the parameters (empty when fine), naming FeSceneParameters' members
/// ("cfl", "slab_min", ...; "faces.profile.duration" for a loaded face's profile).
std::vector<ParameterProblem> check_parameters(const FeSceneParameters& parameters);

/// How the elements are integrated, for logs and summaries.
const char* integration_description(const FeSceneParameters& parameters);
/// The explicit cells' shock viscosity ("shock viscosity q1 / q2" or "no shock viscosity").
std::string shock_viscosity_description(const FeSceneParameters& parameters);

/// Throws std::invalid_argument listing check_parameters' problems, if there are any.
void require_valid(const FeSceneParameters& parameters);
} // namespace vulnus::fem
