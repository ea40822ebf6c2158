// Public interface of the deal.II far-field solver: explicit (central difference, lumped mass)
// and implicit (Newmark, generalized-alpha) dynamics of the slab minus the MPM zone with the
// shared failing material, plus the hooks the MPM-FE coupling uses. The deal.II objects live
// in FarFieldSolver::Data (fem/far_field_data.h), so this header stays light.
#pragma once

#include "fem/fem_parameters.h"
#include "materials/material.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
template <int dim, int spacedim> class Triangulation;
}

namespace vulnus::fem
{
/// One node of the mesh (a support point of the vector element) owned by this rank.
struct NodeRecord
{
  dealii::Point<3> position;                           ///< reference position, m
  std::array<dealii::types::global_dof_index, 3> dofs; ///< x, y, z components
};

/// Bounds on how a far-field cell may move before the adaptive zone takes it (0: not checked).
struct CellMotionLimits
{
  /// Largest departure of an interface cell's node from the cell's best-fit affine motion,
  /// over the cell's size.
  double non_affine = 0.0;
  /// Largest ln(lambda_max / lambda_min) of the cell's best-fit affine stretch.
  double deviatoric_stretch = 0.0;
  /// Smallest corner Jacobian over the largest.
  double jacobian_ratio = 0.0;
};

enum class CellMotionCause
{
  none,
  distortion,
  non_affine_motion
};

/// A far-field cell flagged by its motion: its reference centre and why.
struct FlaggedCell
{
  dealii::Point<3> centre;
  CellMotionCause cause = CellMotionCause::none;
};

/// Whole-mesh figures (summed over ranks; identical on every rank).
struct FeDiagnostics
{
  double time = 0.0;
  unsigned int step = 0;
  double kinetic_energy = 0.0;    ///< J
  double strain_energy = 0.0;     ///< J, intact parts of the material
  double external_work = 0.0;     ///< J, work of tractions and prescribed velocities since t = 0
  /// J, the sum of the steps' positive external work: the energy the loads have put in (a
  /// load may take it back, external_work then falls towards zero while this stays)
  double external_work_in = 0.0;
  double dissipated_energy = 0.0; ///< J, released by failure and plastic work
  dealii::Tensor<1, 3> momentum;  ///< kg m/s
  /// Force the supports and loads exert on the body through each slab face, N; index as
  /// boundary ids (x-, x+, y-, y+, z-, z+, interface). R = f_int + M a - f_ext on the
  /// face's nodes (inertia with the lumped mass).
  std::array<dealii::Tensor<1, 3>, n_slab_faces + 1> face_reactions;
  /// Impulse the supports of each face exerted on the body since t = 0 (the time integral of
  /// their reactions with the integrator's weights; zero on free faces), N s.
  std::array<dealii::Tensor<1, 3>, n_slab_faces + 1> support_impulses;
  /// Quadrature points failed beyond what the far field carries: any failure flag, or under
  /// FailureProximity::total_failure a total failure (matrix failure is carried).
  unsigned long long n_failed_points = 0;
  double max_wave_speed = 0.0;            ///< m/s over quadrature points
};

/// A material point made from a far-field cell (adaptive zone): its reference position and
/// weight, and the fields the FE interpolates there.
struct ConvertedPoint
{
  dealii::Point<3> reference_position;   ///< m
  dealii::Tensor<1, 3> displacement;     ///< m
  dealii::Tensor<1, 3> velocity;         ///< m/s
  dealii::Tensor<2, 3> deformation_gradient;
  materials::PointState state;           ///< failure flags and plastic history
  double reference_volume = 0.0;         ///< m^3, the point's quadrature weight
  double mass = 0.0;                     ///< kg, rho0 times the reference volume
};

/// A far-field point whose tissue has failed, on the MPM lattice: what a conversion would make
/// of its cell, for the wound figures.
struct FailedLatticePoint
{
  dealii::Point<3> reference_position; ///< m
  double reference_volume = 0.0;       ///< m^3
  std::uint8_t failure = 0;            ///< the flag of the Gauss point in its octant
  dealii::Tensor<2, 3> cell_stress;    ///< Pa, its cell's Cauchy stress (debris: a pressure alone)
};

/// Statistics of the last implicit step.
/// Wall-clock seconds of the explicit steps since the start, by phase.
struct FePhaseTimes
{
  double internal_forces = 0.0; ///< material update at the quadrature points and assembly
  double assembly = 0.0;        ///< of those, the cells' forces added in cell order (serial)
  double rest = 0.0;            ///< external forces, vector updates, ghost exchange, constraints
  unsigned long long n_steps = 0;
  unsigned long long quiet_cells_skipped = 0; ///< cell evaluations skipped as at rest
};

struct ImplicitStepStatistics
{
  unsigned int newton_iterations = 0;
  unsigned int linear_iterations = 0; ///< summed over Newton iterations
  double final_residual = 0.0;        ///< N
  unsigned int preconditioner_setups = 0;
  double assembly_seconds = 0.0;       ///< Newton systems: cells' laws, tangents, assembly
  double preconditioner_seconds = 0.0; ///< multigrid set-ups
  double solve_seconds = 0.0;          ///< Krylov iterations
};

/// Finite element far field of the slab (docs/DESIGN.md section 5).
///
/// Total Lagrangian: f_int = int_Omega0 P : grad N dV with P = J sigma F^{-T} from
/// materials::Material::update at every quadrature point; per-point history (failure flags,
/// plastic state) is carried from step to step and updated only when a step is accepted.
///
/// Explicit (central difference in velocity-Verlet form, lumped row-sum mass M):
///   v_{n+1/2} = v_n + dt/2 a_n,  u_{n+1} = u_n + dt v_{n+1/2},
///   a_{n+1} = M^{-1} (f_ext - f_int(u_{n+1})),  v_{n+1} = v_{n+1/2} + dt/2 a_{n+1};
///   stable step dt = cfl * min over cells (h_min / c_max), c from the P-wave modulus.
/// Implicit (Chung & Hulbert 1993, J. Appl. Mech. 60:371, with Newmark as alpha_m = alpha_f = 0):
///   M a_{n+1-alpha_m} + f_int(u_{n+1-alpha_f}) = f_ext(t_{n+1-alpha_f}), consistent mass,
///   alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1), gamma = 1/2 - alpha_m + alpha_f,
///   beta = (1 - alpha_m + alpha_f)^2 / 4; Newton with the consistent tangent dP/dF of the
///   material, Trilinos CG/GMRES with ML algebraic multigrid.
/// Dirichlet velocities (fixed, roller, prescribed, interface) are imposed on the nodes with
/// u_{n+1} = u_n + dt (v_n + v_{n+1})/2 (consistent with gamma = 1/2); hanging nodes follow
/// their masters through AffineConstraints.
///
/// MPI: every call is collective unless stated otherwise.
/// The far field's mesh for output: every vertex once, at its current position, joined into
/// the live (not converted) cells as linear hexahedra (a quadratic element's mid-side nodes are left out).
struct FeMeshForOutput
{
  std::vector<double> positions;    ///< n_vertices x 3, m (reference + displacement)
  std::vector<double> displacement; ///< n_vertices x 3, m
  std::vector<double> velocity;     ///< n_vertices x 3, m/s
  std::vector<std::int32_t> hexahedra; ///< n_cells x 8 vertex indices, XDMF/VTK corner order
  std::vector<double> stress;          ///< n_cells x 6 Cauchy stress, Pa, xx yy zz xy yz xz
  std::vector<std::uint8_t> failure;   ///< n_cells: the most failed flag of the cell's points
  std::vector<std::uint32_t> rank;     ///< n_cells: the owning MPI rank
};

class FarFieldSolver
{
public:
  using VectorFunction = std::function<dealii::Tensor<1, 3>(const dealii::Point<3>&)>;
  using TimeVectorFunction =
      std::function<dealii::Tensor<1, 3>(const dealii::Point<3>&, double time)>;

  /// Checks the parameters (throws std::invalid_argument with all problems) and builds the
  /// material; the mesh is built by setup().
  FarFieldSolver(const FeSceneParameters& parameters, MPI_Comm communicator);
  ~FarFieldSolver();
  FarFieldSolver(const FarFieldSolver&) = delete;
  FarFieldSolver& operator=(const FarFieldSolver&) = delete;

  /// Builds the mesh, calls modify_mesh on it (e.g. to distort it in a test; boundary ids
  /// must stay), distributes dofs, builds constraints, mass, node lists and the initial
  /// accelerations.
  void setup(const std::function<void(dealii::Triangulation<3, 3>&)>& modify_mesh = {});

  /// Initial velocity field (call after setup, before the first step). Prescribed faces
  /// keep their own values; a velocity-driven interface takes (and holds) this field until
  /// set_interface_velocities is called.
  void set_initial_velocity(const VectorFunction& velocity);
  /// Prescribes all velocity components on a slab face by a field v(X, t) (verification,
  /// e.g. a linear field for the patch test); overrides the face condition. Call before setup.
  void set_face_velocity_field(dealii::types::boundary_id face, const TimeVectorFunction& velocity);

  /// Explicit: the stable step of the current state (cfl * h / c). Implicit: the deck step.
  double next_time_step() const;
  /// The shortest time a wave takes to cross a cell at the current state, min h / c over the
  /// live cells (all ranks), s; infinity when no cell has a positive wave speed.
  double shortest_wave_transit() const;
  /// The widest live cell across each slab face (its extent along the face's normal) among
  /// the cells with a face on it (all ranks), m: a support's reaction carries the error of
  /// those widths (docs/far_field.md section 2).
  std::array<double, n_slab_faces> coarsest_cells_on_faces() const;
  /// Advances by dt with the configured integrator. Throws std::runtime_error when an
  /// element inverts or Newton does not converge (the state is then unchanged).
  void advance(double dt);

  double time() const;
  unsigned int step_number() const;
  const FeSceneParameters& parameters() const;
  MPI_Comm communicator() const;

  FeDiagnostics diagnostics() const;
  const ImplicitStepStatistics& last_implicit_step() const;
  /// Explicit steps only (the implicit step reports Newton statistics instead).
  const FePhaseTimes& explicit_phase_times() const;
  unsigned long long n_failed_points() const;
  unsigned long long n_active_cells() const;
  /// Dofs of the live cells (converted cells' own nodes left out).
  unsigned long long n_dofs() const;
  unsigned long long n_quadrature_points() const;

  /// Nodes owned by this rank that belong to a live (not converted) cell, not collective, and
  /// their current fields.
  const std::vector<NodeRecord>& locally_owned_nodes() const;
  dealii::Tensor<1, 3> displacement(const NodeRecord& node) const;
  dealii::Tensor<1, 3> velocity(const NodeRecord& node) const;
  /// Volume-average Cauchy stress of each live locally owned cell (not collective), Pa, with the
  /// cell centres; and the volume average over the whole mesh (collective).
  void locally_owned_cell_stresses(std::vector<dealii::Point<3>>& centres,
                                   std::vector<dealii::Tensor<2, 3>>& stresses) const;
  dealii::Tensor<2, 3> average_cauchy_stress() const;

  // --- coupling hooks -------------------------------------------------------------------
  /// Interface (hole surface) nodes owned by this rank (not collective), in a fixed order;
  /// the per-node vectors below use this order.
  const std::vector<NodeRecord>& interface_nodes() const;
  /// Velocity gradient dv/dx of each interface node (interface_nodes() order), 1/s: the mean
  /// over its live cells of the gradient at their centres. Collective.
  std::vector<dealii::Tensor<2, 3>> interface_velocity_gradients() const;
  /// Lumped (row-sum) FE mass of each interface node, kg.
  std::vector<double> interface_lumped_masses() const;
  /// Force the rest of the FE body transmits to each interface node at the current state, N:
  /// f_ext - f_int - ((M a) - m a) on the node (f_ext - f_int with the lumped mass).
  const std::vector<dealii::Tensor<1, 3>>& interface_nodal_forces() const;
  /// The time integral of interface_nodal_forces over the last step with the integrator's
  /// weights, N s: minus the momentum the rest of the body received through each node.
  const std::vector<dealii::Tensor<1, 3>>& interface_impulses_of_last_step() const;
  /// Force that had to act on the FE body at each interface node to give it its motion,
  /// R = m a - interface_nodal_forces, N; the MPM side feels -R.
  std::vector<dealii::Tensor<1, 3>> interface_reactions() const;
  /// velocity_driven: velocities of the interface nodes at the end of the next step.
  void set_interface_velocities(const std::vector<dealii::Tensor<1, 3>>& velocities);

  // --- interface stiffness of an implicit step (fem/interface_stiffness.cc) --------------
  /// Collective: assembles the implicit step's Newton matrix for a step of dt at the current
  /// state, the interface and supports held, for interface_stiffness_response.
  void prepare_interface_stiffness(double dt);
  /// Collective: the forces this rank's interface nodes need (interface_nodes() order), N,
  /// when the interface dofs `dofs` each move by 1 m at the step's end, the other interface
  /// dofs held and the rest of the body free: for one dof a column of the Newton matrix's
  /// Schur complement on the interface, for several the sum of their columns (probing).
  /// Times interface_mass_factor(dt) it is the effective mass, kg, with which the body
  /// resists a change of the interface velocity at the step's end.
  std::vector<dealii::Tensor<1, 3>>
  interface_stiffness_response(const std::vector<dealii::types::global_dof_index>& dofs) const;
  void release_interface_stiffness();
  /// beta dt^2 / (1 - alpha_f), s^2.
  double interface_mass_factor(double dt) const;

  // --- adaptive zone (fem/far_field_conversion.cc) ---------------------------------------
  /// Collective: the reference centres of the cells (every rank's, on every rank) where a
  /// quadrature point, at the last force evaluation, reached `threshold` of the failure
  /// criterion as FeSceneParameters::failure_proximity measures it (fem/far_field_data.h
  /// failure_proximity: the matrix shear's upper bound, sqrt(2) |dev B| times the measure's
  /// factor, at most 1.16 times the exact value, over its limit, and (fiber stretch - 1) /
  /// (limit - 1)). Needs FeSceneParameters::track_failure_proximity.
  std::vector<dealii::Point<3>> cells_nearing_failure(double threshold) const;
  /// Collective: the live cells (every rank's, on every rank) distorted beyond `limits`, and
  /// the interface cells whose nodes leave the cell's best-fit affine motion by more than
  /// limits.non_affine of its size (fem/cell_motion.h; fem/far_field_cell_motion.cc).
  std::vector<FlaggedCell> cells_moving_unlike_elements(const CellMotionLimits& limits) const;
  /// Collective: material points for this rank's live cells whose centre lies inside
  /// [box_min, box_max]: points_per_axis^3 per cell at the midpoints of equal sub-cells (the MPM
  /// lattice), each with the fields interpolated there and the history of the Gauss point
  /// in its octant. Linear elements only.
  std::vector<ConvertedPoint> material_points_inside(const std::array<double, 3>& box_min,
                                                     const std::array<double, 3>& box_max,
                                                     unsigned int points_per_axis) const;
  /// This rank's failed far-field tissue as lattice points (fem/far_field_conversion.cc):
  /// every live cell with a failed Gauss point gives the midpoints of round(width / spacing)^3
  /// equal sub-cells, as a conversion of a grid-sized cell would, and each failed one is listed
  /// with the flag of the Gauss point of its octant (a midpoint on a cell's mid-plane, with an
  /// odd count, takes the lower octant's). Linear elements.
  std::vector<FailedLatticePoint> failed_lattice_points(double spacing) const;
  /// Collective: switches off every cell whose centre lies inside [box_min, box_max] (cells
  /// already off stay off). They keep their place in the mesh and the dof numbering, so the
  /// rest of the state stays where it is; the faces they share with live cells become
  /// interface faces, the mass and boundary conditions are rebuilt, nodes of no live cell
  /// are held at rest, and the forces are evaluated at the current state.
  void convert_cells_inside(const std::array<double, 3>& box_min,
                            const std::array<double, 3>& box_max);

  /// The evolving state of this rank in binary (collective only through the caller's order);
  /// restore() on a solver set up from the same deck on the same rank count, with the same
  /// cells converted, continues the explicit run bit for bit. Throws std::runtime_error on a mismatch or a short stream.
  void save(std::ostream& out) const;
  void restore(std::istream& in);

  /// Collective: the mesh at the current time for output, gathered on rank 0 (empty on the
  /// other ranks).
  FeMeshForOutput mesh_for_output() const;

  struct Data;

private:
  void evaluate_explicit_forces(double time);
  void advance_explicit(double dt);
  void advance_explicit_staggered(double dt);
  void advance_implicit(double dt);

  std::unique_ptr<Data> data;
};
} // namespace vulnus::fem
