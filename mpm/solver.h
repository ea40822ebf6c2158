// The explicit MPM time step of a scene (update-stress-last family, USL or MUSL):
//   CFL step -> active nodes -> particle-to-grid -> grid update with contact and boundary
//   conditions -> grid-to-particle -> [MUSL re-projection] -> deformation gradients ->
//   stress update -> rigid-body motion -> blow-up checks.
// Each stage is a free function over arrays in its own file; this class owns the state.
#pragma once

#include "core/run_failure.h"
#include "materials/material.h"
#include "mpm/diagnostics.h"
#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/grid_update.h"
#include "mpm/grid_to_particle.h"
#include "mpm/interface_exchange.h"
#include "mpm/neglected_rotation.h"
#include "mpm/nonlocal_failure.h"
#include "mpm/particle_to_grid.h"
#include "mpm/particles.h"
#include "mpm/point_splitting.h"
#include "mpm/projectile_penetration.h"
#include "mpm/projectile_subcycle.h"
#include "mpm/rank_group.h"
#include "mpm/rigid_hold.h"
#include "mpm/scene_parameters.h"
#include "mpm/slab_partition.h"
#include "mpm/stress_update.h"
#include "mpm/symmetry_planes.h"
#include "mpm/transfer_settings.h"

#include <array>
#include <functional>
#include <iosfwd>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vulnus::mpm
{
/// A numerical blow-up detected during a step: the failure names step, time, point, body,
/// position, the likely cause and the remedy.
using vulnus::BlowUp;

/// Wall-clock seconds spent in each stage since the start.
struct PhaseTimes
{
  double time_step = 0.0;
  double particle_to_grid = 0.0;
  double grid_update = 0.0; ///< nodal velocities, forces, face conditions
  double contact = 0.0;     ///< the contact pass (nodes where bodies meet)
  double grid_to_particle = 0.0;
  double nonlocal_failure = 0.0; ///< the nonlocal failure criterion's means
  double stress_update = 0.0;
  double projectile_substeps = 0.0; ///< a subcycled projectile's own steps
  double checks_and_sorting = 0.0;
  double coupling = 0.0; ///< the partner's exchange, including its own step
  double total() const
  {
    return time_step + particle_to_grid + grid_update + contact + grid_to_particle + nonlocal_failure + stress_update +
           projectile_substeps + checks_and_sorting + coupling;
  }
};

/// A point that left the grid: what the wound analysis keeps of it.
struct DepartedPoint
{
  Vector3 reference_position;
  double reference_volume = 0.0; ///< m^3
  std::uint8_t failure = 0;      ///< materials::FailureFlag bits
  std::uint32_t body = 0;
};

/// The projectile when it left the target (mean velocity, kinetic energy): when its tail
/// passed the exit plane, or, in any direction, when none of its points was within a cell of
/// the target any more after it had been.
struct ProjectileExit
{
  bool recorded = false;
  bool past_exit_plane = true;         ///< false: left the target sideways or backwards
  double time = 0.0;                   ///< s
  Vector3 velocity = Vector3::Zero();  ///< m/s, mass-weighted mean
  double kinetic_energy = 0.0;         ///< J
  Vector3 position = Vector3::Zero();  ///< m, mass centre when it left
};

/// Distributed runs (a communicator of several ranks): each rank holds the points of one slab
/// of the grid (SlabPartition); the step's results are the same as on one rank up to the
/// order of floating-point additions. points() is then this rank's share; the diagnostics,
/// time step, contact results, counters and errors are over all ranks, and every public
/// call that says "collective" must be made on every rank.
class Solver
{
public:
  /// `communicator`: MPI_COMM_NULL (or one rank) for a run in one process.
  explicit Solver(const SceneParameters& scene, MPI_Comm communicator = MPI_COMM_NULL);

  /// Replaces the point velocities of the deformable bodies (or of body `body` only) by
  /// field(x) (initial conditions such as a vibration mode), and under APIC their affine
  /// part by its gradient (so the field must be smooth and give the same value for the same
  /// x); resets the initial energy.
  void set_point_velocities(const std::function<Vector3(const Vector3&)>& field, int body = -1);

  /// dt = CFL h / max over deformable points of (wave speed + |v|), rigid bodies by |v| only.
  double stable_time_step() const;

  /// Advances one step of size min(stable step, time left, cap). A finite cap longer than the
  /// stable step (the rest of a coupling window) is split into equal steps, so that the window
  /// never ends on a sliver of a step. Throws BlowUp.
  void advance(double cap = std::numeric_limits<double>::infinity());

  /// Shares grid nodes of one body with a partner solver (the coupling): every step the
  /// partner sees the MPM mass, momentum and force there and sets their velocity. The
  /// partner must outlive the solver or be replaced. Distributed: every rank passes the same
  /// keys; the partner sees the state summed over the ranks (identical on each) and returns
  /// velocities for every key, and each rank uses those of the nodes it holds.
  void share_nodes(const SharedNodes& nodes);
  const SharedNodes& shared_nodes() const { return shared; }

  /// Collective: adds material to body b (the adaptive zone's converted far field). Each
  /// rank passes its own points as a one-body container with position, reference position,
  /// velocity, deformation gradient, mass, reference volume, fiber, failure flags and plastic
  /// histories set; they get fresh ids, their stress, energy and wave speed from the body's
  /// law at their F (their histories unchanged), and move to the ranks whose slabs hold
  /// them. Returns their kinetic plus stored energy, J, over all ranks.
  double add_points(std::size_t b, Particles added);
  /// Points made by splitting stretched points (mpm/point_splitting.h), all ranks.
  std::size_t split_points() const { return n_split; }

  /// True when the end time is reached or the projectile's tail has left the targets.
  /// Collective.
  bool finished() const;

  double time() const { return current_time; }
  std::size_t step_count() const { return n_steps; }
  double last_time_step() const { return time_step; }
  /// This rank's points.
  const Particles& points() const { return particles; }
  /// Every rank's points on rank 0 (an empty container elsewhere). Collective.
  Particles gather_points() const;
  /// Number of points over all ranks. Collective.
  std::size_t n_points_all_ranks() const;
  /// Active grid nodes summed over the ranks (nodes shared by two slabs count twice). Collective.
  std::size_t active_nodes_all_ranks() const;
  const RankGroup& rank_group() const { return ranks; }
  const SlabPartition& slabs() const { return partition; }
  const Grid& background_grid() const { return grid; }
  const SceneParameters& scene() const { return parameters; }
  const materials::Material& body_material(std::size_t b) const { return *materials_of_body[b]; }

  /// Collective.
  SceneDiagnostics diagnostics() const;

  /// Writes the whole evolving state (points, time, step, rigid velocities, accumulated
  /// energies) in binary; restore() on a solver built from the same scene continues the run
  /// bit for bit (same thread count). Throws std::runtime_error on a mismatch or a short file.
  void save(std::ostream& out) const;
  void restore(std::istream& in);
  /// Collective: when the run will most likely end: the end time, or earlier the time at
  /// which the projectile's tail passes the exit plane at its current mean speed.
  double expected_end_time() const;
  /// Index of the projectile body, or -1.
  int projectile() const { return projectile_body; }
  /// The domain faces that are mirror planes of the scene (Grid/Boundary conditions =
  /// symmetry); the solver models the part of the scene inside them.
  const std::vector<SymmetryPlane>& mirror_planes() const { return planes_of_symmetry; }
  /// Axis of the projectile's flight (unit), or +y when there is no projectile.
  const Vector3& flight_direction() const { return flight_axis; }
  /// Where the projectile's path (the line through its mass centre along its flight) enters
  /// and leaves the target's surfaces as the deck draws them, as x . flight_direction().
  std::pair<double, double> target_extent_along_flight() const { return {entrance_plane, exit_plane}; }
  /// false: the path misses the target, and the planes above are its points' extent.
  bool path_crosses_target() const { return path_hits_target; }
  /// Force the other bodies exert on each body in the last step (N).
  const std::vector<Vector3>& contact_forces() const { return grid_result.contact_force; }
  /// Kinetic energy removed by contact since the start (J).
  double contact_dissipation() const { return accumulated_contact_dissipation; }
  /// Kinetic energy the fixed and roller faces' supports removed since the start (J).
  double support_dissipation() const { return accumulated_support_dissipation; }
  /// Largest point speed seen at the start of a step so far, per body (m/s).
  const std::vector<double>& peak_point_speeds() const { return peak_point_speed; }
  /// Largest von Mises / yield seen so far, per body.
  const std::vector<double>& peak_von_mises_over_yield() const { return peak_yield_ratio; }
  /// Points removed because they left the grid, and the kinetic plus stored energy and the
  /// momentum they carried out.
  std::size_t removed_points() const { return n_removed; }
  double removed_energy() const { return outflow_energy; }
  const Vector3& removed_momentum() const { return outflow_momentum; }
  /// Points of this rank that left the grid (removed), as the wound analysis needs them.
  const std::vector<DepartedPoint>& departed_points() const { return departed; }
  /// The projectile's state when its tail passed the exit plane (recorded once, also when the
  /// run goes on after it).
  const ProjectileExit& projectile_exit() const { return exit_record; }
  /// The projectile's depth below the target's entrance plane, step by step, and whether it
  /// stopped or turned back in the target (mpm/projectile_penetration.h).
  const ProjectilePenetration& penetration() const { return penetration_record; }
  /// Impulse the domain faces' supports gave the deformable bodies since the start, by face
  /// (x-, x+, y-, y+, z-, z+), N s. Collective.
  std::array<Vector3, 6> support_impulses() const;
  /// Total energy at the start (J).
  double initial_energy() const { return energy_at_start; }
  /// Momentum of every body (rigid ones included) at the start, kg m/s.
  const Vector3& initial_momentum() const { return momentum_at_start; }
  /// Impulse from outside the bodies and supports since the start, N s: gravity on the
  /// deformable bodies, and what holds a rigid body of prescribed motion on its course
  /// (minus the contact impulse it received).
  const Vector3& external_impulse() const { return accumulated_external_impulse; }
  /// Work the rigid bodies of prescribed motion did on the others since the start (J): the
  /// energy their drive supplied (the body itself keeps its kinetic energy).
  double prescribed_work() const { return accumulated_prescribed_work; }
  /// Momentum brought in by points added to the bodies (add_points), kg m/s.
  const Vector3& added_momentum() const { return accumulated_added_momentum; }
  /// Number of nodes where bodies met in the last step.
  std::size_t contact_nodes() const { return grid_result.n_contact_nodes; }
  /// Active nodes of the last step (kept across a checkpoint, like the contact results).
  std::size_t active_nodes() const { return n_active_last_step; }
  bool uses_contact() const { return contact_active; }
  /// Whether the projectile advances in substeps of its own (Time/Subcycle projectile, for a
  /// deformable projectile with 10 times the others' impedance), and how many it took in the
  /// last step (0: not subcycled).
  bool subcycles_projectile() const { return subcycle != nullptr; }
  /// The deformable projectile held rigid while elastic (Time/Rigid projectile while
  /// elastic): whether it applies, is held now, and why it was released or never held.
  const RigidHold& projectile_hold() const { return rigid_hold; }
  /// A free rigid projectile's rotation that its translation-only motion leaves out
  /// (mpm/neglected_rotation.h); inactive for any other projectile.
  const NeglectedRotation& projectile_rotation() const { return rotation_estimate; }
  int last_projectile_substeps() const { return n_projectile_substeps; }
  const PhaseTimes& phase_times() const { return timings; }

private:
  /// The CFL step; with a non-null argument also each body's fastest point speed (collective).
  /// The CFL step; per body (when asked) the fastest point speed |v| and signal speed c + |v|.
  /// Sets the projectile's FLIP fraction for this step (scene.projectile_velocity_relaxation).
  void relax_projectile_velocities(double dt, const std::vector<double>& signal_speed);
  /// Leading the contact assumes the interface moves with the projectile: its impedance
  /// rho c must exceed every other deformable body's this many times (copper on tissue: 3000).
  static constexpr double minimum_impedance_ratio = 10.0;
  /// Whether the deformable projectile is that much stiffer than the other bodies. Collective.
  bool projectile_is_far_stiffer() const;
  /// Builds the projectile's subcycle when the scene asks for one and it applies (a
  /// deformable projectile far stiffer than the others).
  void plan_projectile_subcycle();
  /// Impedance rho c of each deformable body at the start (its stiffest point), 0 for rigid
  /// ones. Collective.
  std::vector<double> body_impedances() const;
  /// A body's mass, mass centre, inertia about it and farthest point from it.
  struct MassDistribution
  {
    double mass = 0.0;
    Vector3 centre = Vector3::Zero();
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    double radius = 0.0;
  };
  /// Body b's, over all ranks. Collective.
  MassDistribution mass_distribution(std::size_t b) const;
  /// Holds the deformable projectile rigid when the scene asks and the impact allows it
  /// (mpm/rigid_hold.h). Collective.
  void begin_rigid_hold();
  /// Starts the estimate of a free rigid projectile's neglected rotation. Collective.
  void begin_rotation_estimate();
  /// After this step's contact, before the rigid velocities take its force.
  void estimate_projectile_rotation(double dt);
  /// Per body, the exact shape contact takes for it while it is rigid (Contact/Rigid surface
  /// = exact), and half its point spacing; a rigid material's body gets its shape's mass.
  void plan_exact_rigid_surfaces();
  /// Moves the exact shapes of the rigid bodies to where their points are (their mean
  /// displacement from the start). Collective.
  void update_rigid_surfaces();
  /// After this step's contact: the hold's checks. Returns whether they released it.
  bool check_rigid_hold(double dt, const Vector3& velocity_over_step);
  /// Makes the released projectile deformable (subcycled when the scene asks) from the next
  /// step on.
  void make_projectile_deformable();
  /// The projectile's substeps over this step dt (after the other bodies' step). Distributed,
  /// every rank advances the whole projectile (gathered from all) and keeps its own points.
  void advance_projectile_substeps(double dt);
  double step_limit(std::vector<double>* fastest_point_of_body,
                    std::vector<double>* signal_speed_of_body = nullptr) const;
  void sort_points();
  void exchange_shared_nodes(double dt);
  void sum_shared_state_over_ranks();
  /// Sets the interface velocities of the exchange in `velocity` (the grid update's or, for
  /// MUSL, the re-projected nodal velocities).
  /// projected_again: MUSL's second projection (blended with the partner's velocity where it
  /// asks for it, InterfacePartner::blend_masses).
  void impose_shared_velocities(std::vector<Vector3>& velocity, bool projected_again);
  /// Per-point volumetric strain rate for the bulk viscosity, sized to the points; null (no
  /// memory) when the viscosity is off.
  double* volumetric_rate_or_null();
  /// Per body: 1 when its law keeps a plastic history (its points get slots).
  std::vector<char> bodies_with_plastic_history() const;
  void check_state() const;
  RunFailure state_problem() const;
  /// A rigid body with a point beyond a fixed or roller domain face (rigid bodies ignore face
  /// conditions, so it would pass through), described; "" when there is none. Local.
  RunFailure rigid_face_problem() const;
  /// Two rigid bodies met in this step's contact pass (grid_result), described; "" when not.
  RunFailure rigid_meeting_problem(double dt) const;
  /// Whether the run ends when the projectile's tail passes the exit plane.
  bool stops_at_projectile_exit() const;
  /// Collective: the smallest x . flight axis of the projectile's points.
  double projectile_tail() const;
  /// Collective: records the projectile's exit the first time its tail passes the exit plane
  /// or it comes clear of the target (after having been near it).
  void record_projectile_exit();
  /// Collective: the projectile's nose depth and forward speed into the penetration record.
  void record_penetration();
  /// Collective, at the start: the entrance and exit planes on the target's surfaces along
  /// the projectile's path, and the projectile's front beyond its points.
  void measure_path_through_target(const SceneParameters& scene);
  /// Collective: whether a projectile point lies within a cell of the box holding the target's
  /// points that still carry stress (debris, totally failed, is left out).
  bool projectile_near_target() const;
  void plan_slabs();
  void rebalance_slabs();
  void migrate_points(bool to_any_rank);
  void sum_node_data_with_neighbours();
  void sum_projected_momenta_with_neighbours();
  void reduce_contact_result();
  /// Axisymmetric: the step's contact forces and supports' impulses of the revolved scene.
  void revolve_step_results();
  /// XPIC(m): fields.xpic_correction = v*_m - v^n for the points' velocity update; FMPM(m):
  /// the series from v^(n+1) instead, less v^(n+1) (mpm/xpic.h).
  void compute_xpic_correction();
  void remove_points_outside_grid();
  /// Point splitting's limit, box, planes and rigid bodies; refuses what cannot split.
  void plan_point_splitting();
  /// Collective: splits the deformable bodies' points stretched beyond splitting's limit.
  void split_stretched_points();
  /// Collective: gives the points of `added` ids after the largest in use, rank by rank.
  void assign_fresh_ids(Particles& added);
  std::string describe_point(std::size_t p) const;

  SceneParameters parameters;
  RankGroup ranks;
  SlabPartition partition;
  std::vector<char> node_shared_with_lower_rank; ///< per active node, set by the node exchange
  std::vector<std::unique_ptr<materials::Material>> owned_materials;
  std::vector<const materials::Material*> materials_of_body;
  Grid grid;
  Particles particles;
  GridFields fields;
  ScatterBuffers buffers;
  TransferSettings transfer;
  GridUpdateSettings grid_settings;
  GridUpdateResult grid_result;
  KinematicsSettings kinematics;
  std::vector<Vector3> xpic_term; ///< XPIC(m): the series' current term per node and body
  StressUpdateSettings stress_settings;
  StressUpdateResult stress_result;
  std::vector<double> body_mass; // of the points on the grid, on every rank
  std::vector<double> volumetric_rate;
  std::vector<double> peak_yield_ratio;
  std::vector<double> peak_point_speed;
  SharedNodes shared;
  SharedNodeState shared_state;
  std::vector<Vector3> shared_velocity_start, shared_velocity_end;
  std::unique_ptr<ProjectileSubcycle> subcycle;
  RigidHold rigid_hold;
  NeglectedRotation rotation_estimate;
  std::vector<Vector3> projectile_trial_velocity; ///< per active node, before contact
  std::vector<Vector3> projectile_contact_force;  ///< per projectile point of this rank
  int n_projectile_substeps = 0;
  bool nonlocal_failure = false; ///< a body's law asks for the nonlocal failure criterion
  NonlocalFailureCache nonlocal_cache;
  FailureLimitFlags failure_limit_flags; ///< taken by the deformation update for the criterion
  VolumeAveraging volume_averaging;      ///< scratch of the cell-averaged volume change
  bool contact_active = false;
  int projectile_body = -1;
  std::vector<SymmetryPlane> planes_of_symmetry;
  Vector3 flight_axis = Vector3::UnitY();
  double exit_plane = 0.0; ///< x . flight_axis where the path leaves the target's surface
  bool projectile_reached_target = false; ///< a projectile point has been near the target
  double entrance_plane = 0.0; ///< x . flight_axis where the path enters the target's surface
  double nose_offset = 0.0;    ///< the projectile's front beyond its foremost point at the start
  bool path_hits_target = false; ///< false: the planes are the target points' extent

  double current_time = 0.0;
  double time_step = 0.0;
  std::size_t n_steps = 0;
  double accumulated_contact_dissipation = 0.0;
  double accumulated_support_dissipation = 0.0; ///< same on every rank
  double energy_at_start = 0.0;
  Vector3 momentum_at_start = Vector3::Zero();
  Vector3 accumulated_external_impulse = Vector3::Zero(); ///< same on every rank
  double accumulated_prescribed_work = 0.0;               ///< same on every rank
  Vector3 accumulated_added_momentum = Vector3::Zero();   ///< same on every rank
  PhaseTimes timings;
  std::size_t n_removed = 0;
  PointSplitting splitting; ///< longest_edge 0: off
  std::size_t n_split = 0;  ///< same on every rank
  std::size_t n_active_last_step = 0;
  double outflow_energy = 0.0;
  Vector3 outflow_momentum = Vector3::Zero();
  std::vector<DepartedPoint> departed;
  ProjectileExit exit_record;
  ProjectilePenetration penetration_record;
  /// Support impulses of this rank's nodes since the start.
  std::array<Vector3, 6> support_impulse_here = {Vector3::Zero(), Vector3::Zero(), Vector3::Zero(),
                                                 Vector3::Zero(), Vector3::Zero(), Vector3::Zero()};
};
} // namespace vulnus::mpm
