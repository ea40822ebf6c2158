// Internal state of FarFieldSolver (deal.II objects, vectors, quadrature-point history),
// shared by the solver's implementation files only; not part of the public interface.
#pragma once

#include "fem/far_field_solver.h"
#include "materials/material.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>

#include <array>
#include <utility>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace vulnus::fem
{
/// Where the velocity of a Dirichlet dof comes from.
enum class DirichletSource : unsigned char
{
  zero,          ///< fixed or roller
  face_constant, ///< FaceParameters value * g(t) of face `index`
  face_field,    ///< field set by set_face_velocity_field on face `index`
  interface      ///< interface node `index` (velocity_driven)
};

struct DirichletDof
{
  dealii::types::global_dof_index dof;
  unsigned int component;
  DirichletSource source;
  unsigned int index;
  dealii::Point<3> position;
  /// Boundary id whose condition constrains the dof (interface: boundary_ids::interface).
  dealii::types::boundary_id face = 0;
};

/// Forces across the constrained boundary at one state, N (this rank's nodes):
///   interface[n]  what the rest of the body transmits to interface node n,
///                 X = f_ext - f_int - ((M a) - m a) on the node (lumped mass: f_ext - f_int);
///   supports[b]   the force part of what the supports of face b exert on the body,
///                 f_int - f_ext summed over the face's constrained dofs (their inertia,
///                 m a, is booked as m dv in integrate_boundary_forces).
/// Over a step the body's momentum changes by the time integrals of the supports' R and the
/// interface's m a - X (docs/DESIGN.md section 6).
struct BoundaryForces
{
  std::vector<dealii::Tensor<1, 3>> interface;
  std::array<dealii::Tensor<1, 3>, n_slab_faces + 1> supports;
};

/// Sums of one pass over the quadrature points (local to this rank).
struct EvaluationSums
{
  double strain_energy = 0.0;
  double dissipated = 0.0;
};

/// Matrix, preconditioner and work vectors of the implicit integrators
/// (fem/implicit_integrator.cc).
struct ImplicitData;
/// The implicit step's interface stiffness (fem/interface_stiffness.cc).
struct InterfaceStiffnessData;

struct FarFieldSolver::Data
{
  using Vector = dealii::TrilinosWrappers::MPI::Vector;

  Data(const FeSceneParameters& parameters, MPI_Comm communicator);

  FeSceneParameters prm;
  MPI_Comm comm;
  std::unique_ptr<materials::Material> material;

  /// A serial triangulation on one MPI rank, a p4est one on several: p4est orders its coarse
  /// cells hierarchically at set-up, and every cell of the graded slab mesh is a coarse cell
  /// (minutes and gigabytes for the millions of a fine far field).
  std::unique_ptr<dealii::Triangulation<3>> owned_triangulation;
  dealii::Triangulation<3>& triangulation;
  dealii::FESystem<3> fe;
  dealii::DoFHandler<3> dof_handler;
  dealii::MappingQ1<3> mapping;
  dealii::QGauss<3> quadrature;      ///< the law's points (one with one-point integration)
  dealii::QGauss<3> mass_quadrature; ///< (degree + 1)^3 points: lumped and consistent mass
  dealii::QGauss<2> face_quadrature;

  dealii::IndexSet owned_dofs;
  dealii::IndexSet relevant_dofs;
  dealii::AffineConstraints<double> hanging_constraints; ///< hanging nodes only
  /// Hanging nodes plus homogeneous Dirichlet rows: constraints of Newton increments.
  dealii::AffineConstraints<double> increment_constraints;
  std::vector<DirichletDof> dirichlet_dofs; ///< owned only
  /// Owned (dof, component) pairs on each boundary id.
  std::array<std::vector<std::pair<dealii::types::global_dof_index, unsigned int>>,
             n_slab_faces + 1>
      face_dofs;
  std::array<TimeVectorFunction, n_slab_faces> face_fields;

  std::vector<NodeRecord> owned_nodes;
  std::vector<NodeRecord> interface_nodes;
  std::vector<dealii::Tensor<1, 3>> interface_velocity_targets;

  // Owned vectors: displacement, velocity, acceleration, lumped mass (condensed), inverse
  // lumped mass (zero on constrained dofs), internal and external forces without constraints.
  Vector displacement, velocity, acceleration;
  Vector lumped_mass, inverse_mass;
  Vector internal_force_raw, external_force_raw;
  /// Implicit: (M a)_i - m_i a_i at the last Newton state, consistent minus lumped inertia
  /// (zero for the explicit lumped mass).
  Vector inertia_coupling_raw;
  Vector residual; ///< explicit: condensed f_ext - f_int
  // Ghosted copies for cell loops: the displacement, and the explicit step's velocity for the
  // shock viscosity.
  Vector ghosted, ghosted_velocity;

  unsigned int n_q_points = 0;
  std::vector<materials::PointState> committed_states;
  std::vector<materials::PointState> trial_states;
  std::vector<Eigen::Vector3d> fiber_directions; ///< per quadrature point
  std::vector<dealii::Tensor<2, 3>> cell_stress; ///< by active cell index
  std::vector<unsigned char> cell_failure;       ///< max flag over the cell's points
  std::vector<double> cell_wave_speed;           ///< m/s
  /// prm.track_failure_proximity: the largest over the cell's points of failure_proximity.
  std::vector<double> cell_failure_proximity;
  std::vector<double> cell_size;                 ///< smallest vertex distance / degree, m
  /// Quiet cells: a cell none of whose nodes has moved more than this fraction of its size
  /// and whose points are intact and never yielded is still at rest (strains below about
  /// 1e-12); the explicit force evaluation skips it and keeps its rest stress, wave speed
  /// and zero force. Off for the first evaluation after setup, which computes the rest values.
  static constexpr double quiet_displacement_over_size = 1e-12;
  bool skip_quiet_cells = false;
  bool is_quiet(const std::vector<double>& u_local, double size, std::size_t first_point) const;
  /// Local positions in the ghosted vectors of each owned cell's dofs (by active cell index,
  /// n_dofs_per_cell each), so the cell loop reads values without a global-to-local lookup.
  std::vector<int> cell_local_dofs;
  /// This rank's live cells in mesh order, filled with cell_local_dofs: the force
  /// evaluation's threads share them out, then add their forces (cell_force_values, n_dofs per
  /// live cell) in this order.
  std::vector<dealii::DoFHandler<3>::active_cell_iterator> live_cells;
  std::vector<double> cell_force_values;
  /// For each owned dof (local index l), where its live cells' forces sit in
  /// cell_force_values, in cell order: owned_dof_forces[owned_dof_force_begin[l] ...
  /// owned_dof_force_begin[l + 1]). The threads sum each dof's forces in that order.
  std::vector<std::size_t> owned_dof_force_begin;
  std::vector<std::size_t> owned_dof_forces;
  /// The entries of cell_force_values whose dof another rank owns, in cell order.
  struct GhostForce
  {
    std::size_t entry;
    dealii::types::global_dof_index dof;
  };
  std::vector<GhostForce> ghost_dof_forces;
  void index_cell_dofs(const Vector& ghosted_layout);

  /// The explicit force pass's geometry (fem/cell_shapes.cc). The mesh is the reference
  /// configuration, so a cell's shape-function gradients and JxW never change; cells that
  /// are translations of each other (every vertex offset equal to 1e-10 of the cell's size)
  /// share one entry, as FEValues would reuse them: gradients[q * n_nodes + a] of the scalar
  /// shape function a (of the base element, n_nodes of them) at point q, jxw[q].
  /// With one-point integration also the hourglass stiffness per unit shear modulus in cell
  /// dof order (hourglass[i * n_dofs + j], fem/hourglass.h); empty otherwise.
  struct CellShape
  {
    std::vector<Eigen::Vector3d> gradients;
    std::vector<double> jxw;
    std::vector<double> hourglass;
  };
  /// Shear modulus times Far field/Hourglass coefficient (Pa), 0 with full integration.
  double hourglass_modulus = 0.0;
  std::vector<CellShape> cell_shapes;
  std::vector<unsigned int> live_cell_shape; ///< by live cell: its entry of cell_shapes
  std::vector<unsigned int> dof_node;        ///< by cell dof: its scalar shape function
  std::vector<unsigned int> dof_component;   ///< by cell dof: the component it moves
  /// Fills cell_shapes, live_cell_shape, dof_node and dof_component for live_cells.
  void index_cell_shapes();

  /// Boundary forces at the current state and their integrals: over the last step for the
  /// interface nodes, since the start (this rank) for the supports.
  BoundaryForces boundary_now;
  /// Generalized alpha: the boundary forces of the step's converged system, at t_{n+1-af}
  /// (u_{n+1-af}, a_{n+1-am}), taken before finish_step evaluates the end state; consumed by
  /// integrate_boundary_forces of the same step.
  BoundaryForces boundary_alpha;
  std::vector<dealii::Tensor<1, 3>> interface_impulse_last_step;
  std::array<dealii::Tensor<1, 3>, n_slab_faces + 1> support_impulse;
  /// Velocity of each Dirichlet dof when its support impulse was last booked: the supports'
  /// impulse takes each supported dof's momentum change exactly (m dv), not through the
  /// integrator's weights of an acceleration that a prescribed velocity defines only
  /// approximately. Reset with the current velocities where boundary_now is reset.
  std::vector<double> dirichlet_velocity_booked;
  void reset_booked_dirichlet_velocities();
  /// Adds one step's external work to external_work (and, if positive, external_work_in).
  void book_external_work(const double work)
  {
    external_work += work;
    external_work_in += std::max(work, 0.0);
  }

  EvaluationSums last_sums;
  FePhaseTimes phase_times;
  double time = 0.0;
  unsigned int step = 0;
  double external_work = 0.0;
  double external_work_in = 0.0; ///< the steps' positive external work: what loads put in
  double last_power = 0.0;
  double dissipated_energy = 0.0;
  unsigned long long n_failed_points = 0;
  unsigned long long last_warned_failures = 0;
  ImplicitStepStatistics implicit_statistics;
  std::shared_ptr<ImplicitData>
      implicit; ///< matrix and preconditioner (shared_ptr: incomplete type)
  std::shared_ptr<InterfaceStiffnessData> interface_stiffness;

  /// Adaptive zone: cells whose material became points (by active cell index, every cell
  /// of the mesh, artificial ones included, decided by its centre; empty before the first
  /// conversion). They stay in the mesh and its dof numbering but take no part: no mass, no
  /// forces, no output; their faces next to live cells are interface faces.
  std::vector<unsigned char> cell_converted;
  unsigned long long n_converted_cells = 0; ///< over the whole mesh
  /// Live cells (owned or ghost) with an owned interface node, each with the index in
  /// interface_nodes of its vertices (-1: not an owned interface node); built for
  /// interface_cells_built_for converted cells (fem/interface_velocity_gradient.cc).
  std::vector<std::pair<dealii::DoFHandler<3>::active_cell_iterator, std::array<int, 8>>>
    interface_cells;
  unsigned long long interface_cells_built_for = ~0ull;
  /// Owned dofs of no live cell: no mass, held at rest, a unit-mass row in the implicit
  /// matrix (scaled by dead_dof_mass).
  std::vector<dealii::types::global_dof_index> dead_dofs;
  unsigned long long n_dead_dofs = 0; ///< over all ranks
  double dead_dof_mass = 0.0;

  template <class CellIterator>
  bool is_converted(const CellIterator& cell) const
  {
    return !cell_converted.empty() && cell_converted[cell->active_cell_index()] != 0;
  }
  /// Locally owned and not converted: the cells every loop of the solver works on.
  template <class CellIterator>
  bool owns_live(const CellIterator& cell) const
  {
    return cell->is_locally_owned() && !is_converted(cell);
  }

  bool is_implicit() const { return prm.integrator != TimeIntegrator::central_difference; }

  /// The step over which the trial states are reached from the committed ones (s), for
  /// rate-dependent laws; set by the integrators before they evaluate (0 before the first).
  double material_time_step = 0.0;

  /// Velocity of a Dirichlet dof at time t.
  double dirichlet_velocity(const DirichletDof& d, double t) const;

  /// One pass over the live owned cells at the displacement `u` (ghosted), shared among the
  /// threads: updates the trial states from the committed ones, the cell stress, failure, wave
  /// speed and failure proximity, and adds
  /// f_int to internal_force_raw (zeroed first) and, when condensed is non-null, -f_int to
  /// *condensed through the hanging-node constraints. With a velocity (ghosted) the stress
  /// carries prm.shock_viscosity at the rate of the law's volume change, and its work over
  /// material_time_step is booked as dissipated. Throws (on all ranks) when an element inverts.
  EvaluationSums evaluate_internal_forces(const Vector& u_ghosted, Vector* condensed,
                                          const Vector* v_ghosted = nullptr);
  /// The failure criterion whose proximity the cells track, or null when none is tracked.
  const materials::FailureParameters* proximity_criterion() const;
  /// Makes the trial states the committed ones; counts failed points and warns loudly.
  void commit_states();
  /// Assembles f_ext(t) into external_force_raw (tractions and interface forces) and adds
  /// it to *condensed when non-null.
  void assemble_external_forces(double t, Vector* condensed);
  /// The boundary forces at the current state (from the raw force vectors).
  BoundaryForces boundary_forces() const;
  /// After a step of dt: integrates the boundary forces over it with the integrator's weights
  /// (staggered central difference: the start state; otherwise (1 - gamma) start + gamma end)
  /// and makes the end state current.
  void integrate_boundary_forces(double dt);
  /// External power v . F_out (see FeDiagnostics::external_work).
  double external_power() const;
  /// Kinetic energy 1/2 v.M v: lumped mass (explicit) or consistent mass (implicit).
  double kinetic_energy() const;
};

/// The vector component of each dof of a cell (system_to_component_index's first entry).
inline std::vector<unsigned int> dof_components(const dealii::FESystem<3>& fe)
{
  std::vector<unsigned int> component(fe.n_dofs_per_cell());
  for (unsigned int i = 0; i < component.size(); ++i)
    component[i] = fe.system_to_component_index(i).first;
  return component;
}

/// The Newmark velocity weight gamma of the configured integrator (1/2 for the explicit and the
/// average-acceleration steps).
double integrator_gamma(const FeSceneParameters& prm);
/// The implicit integrator's beta, alpha_m and alpha_f (Newmark: 1/4, 0, 0).
double implicit_beta(const FeSceneParameters& prm);
double implicit_alpha_m(const FeSceneParameters& prm);
double implicit_alpha_f(const FeSceneParameters& prm);
/// The implicit step builds its multigrid hierarchy afresh at its next solve. Called where a
/// checkpoint is written, so that a run restarted there and the run that goes on solve with
/// the same hierarchies (bit for bit the same steps).
void forget_implicit_preconditioner(FarFieldSolver::Data& d);

/// The failure proximity of one point with failure flags `failure`
/// (FeSceneParameters::track_failure_proximity): of its matrix, the shear's upper bound over
/// its limit; of its fibers (when it has a fiber), (stretch - 1) / (limit - 1); of a part that
/// has failed, infinity. any_failure: the larger of the two (infinity once either failed);
/// total_failure: the smaller (the part that fails last).
double failure_proximity(const materials::FailureParameters& criterion, const Eigen::Matrix3d& F,
                         const Eigen::Vector3d* fiber, std::uint8_t failure,
                         FailureProximity measure);

/// Collective: the owned nodes, boundary faces (the converted cells' faces next to live cells
/// among the interface faces), Dirichlet dofs, interface nodes, dead dofs and lumped mass, for
/// the current set of converted cells.
void build_boundaries_and_mass(FarFieldSolver::Data& d);

/// Collective: if `failed` is true on any rank, throws std::runtime_error on every rank with the
/// first failing rank's message (prefixed with that rank on the others).
void throw_if_any(bool failed, const std::string& message, MPI_Comm comm);
} // namespace vulnus::fem
