// The hybrid MPM-FE time loop (docs/DESIGN.md section 6): the MPM solver of the zone and the
// deal.II far field, coupled through interface nodes that coincide with MPM grid nodes.
//   same step:  one dt = min(MPM stable step, FE stable step); every shared node keeps one
//               velocity (the FE interface velocity), accelerated by the summed MPM and FE
//               forces over the summed masses; both sides use it (momentum is conserved to
//               round-off, a uniform deformation stays uniform).
//   multi step: the FE side advances over a window of several MPM substeps (explicit at its
//               own CFL step, or implicit Newmark / generalized-alpha); at the window start
//               the interface velocity is advanced with the summed masses and forces, the FE
//               takes its step with it, and the MPM substeps see the FE interface velocity
//               interpolated in time (constant for the explicit staggered velocity, linear
//               for the implicit end-of-step velocities, evaluated at substep midpoints), so
//               both sides' interface displacements agree at every window end.
// Impulse correction: over a window the MPM substeps' forces differ from the first one the
// prediction used, and the FE body transmits over its step what its integrator integrates
// (not its start force alone). Both are measured: the FE side books the impulse its body
// really transmitted, the MPM side the reactions of every substep. The momentum a window
// created, node by node, is taken back in the next window's prediction, so momentum is
// exchanged exactly, one window late (the same-step scheme with the explicit far field
// creates none).
// Balanced windows (implicit far field, coupling/balanced_windows.cc): that lagged feedback
// is unstable beyond short windows, so each window balances its own momentum: the substeps
// steer the interface with the far field's effective interface mass over the window, and the
// last substep closes the balance by re-stepping the far field from the window's start.
#pragma once

#include "coupling/decomposition.h"
#include "coupling/interface_ledger.h"
#include "fem/far_field_solver.h"
#include "mpm/solver.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <mpi.h>

#include <deal.II/base/tensor.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vulnus::coupling
{
/// Why the adaptive zone took a far-field cell: its material neared failure, an interface
/// node of it moved too far, or it is distorted beyond what an element follows.
enum class ZoneCause
{
  failure,
  interface_motion,
  distortion
};
constexpr int n_zone_causes = 3;
using ZoneFlags = std::array<std::uint64_t, n_zone_causes>;

/// One growth of the adaptive zone.
struct ZoneConversion
{
  double time = 0.0;          ///< s
  std::uint64_t mpm_step = 0;
  std::array<double, 3> zone_min{{0.0, 0.0, 0.0}}; ///< the zone after it, m
  std::array<double, 3> zone_max{{0.0, 0.0, 0.0}};
  std::uint64_t cells = 0;    ///< far-field cells removed
  std::uint64_t points = 0;   ///< material points made of them
  double volume = 0.0;        ///< reference volume converted, m^3
  double mass = 0.0;          ///< kg
  /// Kinetic plus strain energy of both sides and the total momentum (with the impulse in
  /// transit) just before and after, J and kg m/s.
  double energy_before = 0.0, energy_after = 0.0;
  Eigen::Vector3d momentum_before = Eigen::Vector3d::Zero();
  Eigen::Vector3d momentum_after = Eigen::Vector3d::Zero();
  double seconds = 0.0; ///< wall-clock time of the conversion
  /// Cells (or interface nodes) inside the limit that asked for it, by ZoneCause; all zero
  /// when the whole limit converts because the far field has no stiffness left.
  ZoneFlags flagged{{0, 0, 0}};
};

class HybridSolver : public mpm::InterfacePartner
{
public:
  /// Builds both sides and matches every FE interface node to an MPM grid node (throws
  /// std::invalid_argument naming a node that does not match). Collective: the MPM side is
  /// distributed over the ranks of `communicator` in slabs, the FE side by deal.II's partition.
  /// before_fe_setup may prescribe FE face fields (verification problems).
  HybridSolver(const HybridScene& scene, MPI_Comm communicator,
               const std::function<void(fem::FarFieldSolver&)>& before_fe_setup = {});
  ~HybridSolver() override;

  /// Replaces the velocity of the split body on both sides by field(x) (initial conditions).
  void set_initial_velocity(const std::function<mpm::Vector3(const mpm::Vector3&)>& field);

  /// One MPM step (and the FE step it triggers). Throws mpm::BlowUp or std::runtime_error.
  void advance();
  bool finished() const;
  double time() const { return mpm_solver->time(); }

  mpm::Solver& mpm() { return *mpm_solver; }
  const mpm::Solver& mpm() const { return *mpm_solver; }
  fem::FarFieldSolver& fe() { return *fe_solver; }
  const fem::FarFieldSolver& fe() const { return *fe_solver; }
  const HybridScene& scene() const { return split; }
  const InterfaceLedger& ledger() const { return book; }
  std::size_t n_interface_nodes() const { return keys.size(); }
  /// Interface = following: the interface nodes are spread over the grid nodes around where
  /// they are now (coupling/following_interface.cc).
  bool follows_interface() const
  {
    return split.hybrid.interface == InterfacePlacement::following;
  }
  /// The grid nodes the interface shares with the MPM side now (its nodes' home grid nodes
  /// unless it follows them).
  std::size_t n_shared_grid_nodes() const { return follows_interface() ? grid_keys.size() : keys.size(); }
  /// Interface nodes whose FE owner rank is not the rank of the MPM slab holding the grid
  /// node (at the start; 0 on one rank).
  std::size_t n_interface_nodes_across_ranks() const { return fe_nodes_on_other_mpm_ranks; }

  /// Total momentum of both sides, kg m/s (FE with its lumped mass), plus the impulse the
  /// next window gives back (impulse_in_transit): constant to round-off at window ends.
  Eigen::Vector3d total_momentum() const;
  /// Momentum the last closed window created, still to be taken back, kg m/s (minus).
  Eigen::Vector3d impulse_in_transit() const;
  /// True between MPM steps that end an FE window (always for the same-step scheme).
  bool at_window_end() const { return !window_open; }
  /// Kinetic + strain energy of the FE side, J.
  double fe_mechanical_energy() const;
  /// Multi-step windows of an implicit far field, which balance their momentum within the
  /// window (coupling/balanced_windows.cc).
  bool balances_windows() const;
  /// Implicit windows coupled through a dashpot (Hybrid/Window coupling = dashpot).
  bool dashpot_windows() const
  {
    return balances_windows() && split.hybrid.window_coupling == WindowCoupling::dashpot;
  }
  /// Up to this many interface dofs (default 750) the far field's effective interface mass
  /// takes one far-field solve per dof (exact); beyond, it is probed (3 x 5^3 = 375 solves,
  /// entries within 2 grid nodes of their dof kept).
  std::size_t exact_balance_dofs() const { return exact_balance_limit; }
  void set_exact_balance_dofs(const std::size_t n) { exact_balance_limit = n; }
  /// The effective interface mass of the current window length, 3 per key, kg.
  const Eigen::SparseMatrix<double>& effective_interface_mass() const { return balance_matrix; }
  /// Probing: interface nodes of one probe are 5 grid nodes apart along some axis, so a
  /// response within 2 nodes of a probed dof is that dof's alone.
  static constexpr int probe_period = 5;
  static constexpr int probe_reach = 2;
  static_assert(probe_period == 2 * probe_reach + 1);

  // --- adaptive zone (coupling/adaptive_zone.cc) -----------------------------------------
  /// The zone now (it grows with the adaptive zone), m.
  const std::array<double, 3>& zone_min() const { return split.hybrid.zone_min; }
  const std::array<double, 3>& zone_max() const { return split.hybrid.zone_max; }
  const std::vector<ZoneConversion>& conversions() const { return zone_conversions; }
  /// Kinetic plus strain energy the conversions changed, summed, J (negative: lost).
  double conversion_energy_change() const
  {
    double sum = 0.0;
    for (const ZoneConversion& c : zone_conversions)
      sum += c.energy_after - c.energy_before;
    return sum;
  }
  /// Reference volume converted so far, m^3.
  double converted_volume() const
  {
    double sum = 0.0;
    for (const ZoneConversion& c : zone_conversions)
      sum += c.volume;
    return sum;
  }
  /// The most cells nearing failure and interface nodes moved too far, at one check, that
  /// the zone could not take in with their margin because its limit was in the way.
  std::uint64_t cells_beyond_limit() const { return n_cells_beyond_limit; }
  /// The split body's share held by the MPM zone, averaged over the run's time so far
  /// (coupling/zone_fraction.cc).
  double time_averaged_zone_fraction() const;
  /// Wall-clock seconds spent checking where the zone must grow, and converting.
  double zone_check_seconds() const { return check_seconds; }
  double zone_conversion_seconds() const
  {
    double sum = 0.0;
    for (const ZoneConversion& c : zone_conversions)
      sum += c.seconds;
    return sum;
  }
  /// Collective: grows the zone to [new_min, new_max] (on grid nodes, holding the zone, within
  /// the limit): the far-field cells inside become material points of the split body, the
  /// far field is rebuilt without them and takes over the rest of its state, and the
  /// interface moves to the new zone's surface. Call between steps at a window end.
  /// `flagged`: what asked for it, by ZoneCause (none when the whole limit converts because
  /// the far field has no stiffness left, or when a caller grows the zone by hand).
  void grow_zone(const std::array<double, 3>& new_min, const std::array<double, 3>& new_max,
                 const ZoneFlags& flagged = {});
  /// True once the zone holds the whole split body: the far field has no cell left (its
  /// supports' impulses and energies stay as they were) and the run goes on as pure MPM.
  bool far_field_retired() const { return retired; }

  /// Both sides' states and the coupling's own (window, interface velocities, corrections,
  /// ledger) in binary; restore() on a solver built from the same deck on the same rank count
  /// continues the run bit for bit, with an explicit or an implicit far field, at a window's
  /// end or in its middle.
  void save(std::ostream& out) const;
  void restore(std::istream& in);

  void exchange(double time, double dt, const mpm::SharedNodeState& mpm_side,
                std::vector<mpm::Vector3>& velocity_start,
                std::vector<mpm::Vector3>& velocity_end) override;
  /// A following interface: the interface's mass at each shared grid node.
  const std::vector<double>* blend_masses() const override
  {
    return follows_interface() ? &grid_fe_share : nullptr;
  }

private:
  /// The zone the far field's flagged cells need, and what each rule flagged inside the limit.
  struct ZoneNeed
  {
    std::array<double, 3> min, max;
    ZoneFlags flagged;
  };
  /// Adaptive zone: the box the zone must grow to so that every place a rule flags sits
  /// inside with the margin (the zone itself when none does). Collective.
  ZoneNeed zone_needed();
  /// Collective, at a window end: a far field with no cell that carries stress left (all
  /// failed) converts whole, when the limit reaches the body's faces (else throws a
  /// RunFailure-style error naming the remedy), and retires.
  void retire_far_field_without_stiffness();
  /// After a conversion: a far field with no live cell retires (the MPM side stops sharing
  /// nodes with it).
  void retire_far_field_if_empty();
  /// Builds the far field for the current split.fe (setup and the initial velocity).
  std::unique_ptr<fem::FarFieldSolver> build_far_field() const;
  /// Lists every FE interface node by its grid key on every rank (sorted) and sums the FE
  /// masses there.
  void match_interface_nodes(MPI_Comm communicator);
  /// fe_velocity and fe_force of every interface node, from the FE ranks owning them.
  void gather_fe_interface_state();
  /// Shared-node velocity after a step dt: v + dt (f_mpm + f_fe) / (m_mpm + m_fe), with v the
  /// node's own (the FE interface) velocity.
  void predict_interface(double dt, const mpm::SharedNodeState& mpm_side);
  /// Drives the far field's interface with velocity_end over dt and returns, by key, the
  /// momentum its interface nodes received beyond what its body transmitted (not booked).
  std::vector<mpm::Vector3> step_fe(double dt);
  /// Books an FE step's interface impulses in the ledger and the window's created momentum.
  void book_fe_side(const std::vector<mpm::Vector3>& impulse);
  void advance_fe(double dt);
  /// exchange() for balanced windows: the far field steps at the window's start with the
  /// predicted end velocities; every substep moves the interface towards the end velocities
  /// that would balance the window's momentum with the substep's MPM force held; the last
  /// substep balances it (balance_window) and books the far field's final step.
  void exchange_balanced(double time, double dt, bool first_substep, bool last_substep,
                         const mpm::SharedNodeState& mpm_side,
                         std::vector<mpm::Vector3>& v_start, std::vector<mpm::Vector3>& v_end);
  /// exchange() for dashpot windows (Window coupling = dashpot): at the window's start the far
  /// field's free step gives its mean free interface velocity; every substep solves the shared
  /// nodes' velocity against the MPM side's kick and a dashpot of the far field's effective
  /// interface mass; the last substep steps the far field with the impulse the MPM side took.
  void exchange_dashpot(double time, double dt, bool first_substep,
                        const mpm::SharedNodeState& mpm_side, std::vector<mpm::Vector3>& v_start,
                        std::vector<mpm::Vector3>& v_end);
  /// Re-steps the far field from the window's start until its interface nodes receive
  /// `target` (by key) beyond what its body transmits, with balance_free_solver's chord
  /// iteration (an unconverged one is booked); returns chord_iterate's residual left.
  double step_fe_to_impulse(double window, const std::vector<mpm::Vector3>& target);
  /// A dashpot window's free step, halving the window (window_end moves) while the far field
  /// cannot take it: its step fails, or the chord iteration does not find the free end.
  void dashpot_free_step(const mpm::SharedNodeState& mpm_side, double dt);
  /// After a dashpot window's far-field step, which left `residual` of its impulse unmet
  /// (relative): later windows are halved if that is beyond window_residual_tolerance or the
  /// far field received more work than the MPM side gave.
  void check_dashpot_window(double residual);
  /// Halves the dashpot windows from now on (down to one wave transit of the far field's
  /// smallest cell, and to no less than `dt`); false if they were that short already.
  bool halve_dashpot_windows(double window, double dt);
  /// The balance's tolerance for a window, kg m/s (balance_scale updated with the interface's
  /// momentum, its masses the FE ones plus mpm_mass if given).
  double window_balance_tolerance(double window, const std::vector<double>& mpm_mass);
  /// Newton's chord iteration of a window: while residual(g) (its largest component) exceeds
  /// the tolerance, velocity_end moves by -solver.solve(g) and the far field re-steps from the
  /// window's start; books the re-steps and an unconverged window. The far field ends at the
  /// best guess met (a guess whose step fails ends the iteration). Returns the residual left
  /// relative to the interface's momentum scale (0 if converged).
  double chord_iterate(double window, const Eigen::SparseLU<Eigen::SparseMatrix<double>>& solver,
                     double tolerance, const std::function<double(Eigen::VectorXd&)>& residual);
  /// dashpot_solver for substeps of window / dt = ratio with these MPM masses.
  void factor_dashpot(double ratio, const std::vector<double>& mpm_mass);
  /// Last substep of a balanced window: finds the interface end velocities for which the
  /// window creates no momentum, each guess evaluated by the far field's step from the
  /// window's start; the MPM side's last substep goes from v_start to them.
  void balance_window(double window, double dt, const mpm::SharedNodeState& mpm_side,
                      const std::vector<mpm::Vector3>& v_start);
  /// The far field's effective interface mass over a window (its Newton matrix's Schur
  /// complement on the interface: one far-field solve per interface dof, or probed beyond
  /// exact_balance_dofs) into balance_matrix.
  void build_balance_matrix(double window);
  /// The interface's forces (factor times the far field's, summed over ranks, 3 per key)
  /// when the interface dofs `probe` (indices 3 k + c) move by 1 m.
  void interface_response(const std::vector<double>& fe_dofs, const std::vector<std::size_t>& probe,
                          double factor, std::vector<double>& response) const;
  /// The balance's chord matrix for this window: balance_matrix plus the MPM nodal masses,
  /// identity rows for components a support holds.
  void factor_balance_matrix(const std::vector<double>& mpm_mass);
  /// balance_matrix plus `diagonal` (3 per key: per node) factored into `solver`, identity rows
  /// for components a support holds.
  void factor_effective_mass(const std::vector<double>& diagonal,
                             Eigen::SparseLU<Eigen::SparseMatrix<double>>& solver) const;
  /// Into g (3 per key): the momentum a balanced window creates at each shared node if its end
  /// velocity is velocity_end and this substep's MPM force holds for `remaining` seconds;
  /// returns its largest component, kg m/s.
  double creation_residual(const mpm::SharedNodeState& mpm_side,
                           const std::vector<mpm::Vector3>& v_start, double remaining,
                           Eigen::VectorXd& g) const;
  /// Starts a window: the momentum the last one created becomes the correction.
  void start_window_correction();
  /// A window's first substep, for balanced and dashpot windows alike: the correction, the
  /// interface's predicted velocities, and the far field's state at the window's start kept
  /// for its re-steps.
  void open_implicit_window(double window, const mpm::SharedNodeState& mpm_side);
  void book_mpm_side(double dt, const mpm::SharedNodeState& mpm_side,
                     const std::vector<mpm::Vector3>& velocity_start,
                     const std::vector<mpm::Vector3>& velocity_end);
  /// The MPM side's velocities over a substep of an explicit window, from the shared nodes'
  /// velocities at the window's start and end (at its end throughout, staggered).
  void substep_velocities(double time, double dt, bool first_substep,
                          const std::vector<mpm::Vector3>& window_start_velocity,
                          const std::vector<mpm::Vector3>& window_end_velocity,
                          std::vector<mpm::Vector3>& v_start, std::vector<mpm::Vector3>& v_end) const;

  // --- following interface (coupling/following_interface.cc) -----------------------------
  /// Spreads every interface node over the grid nodes around its current position
  /// (trilinear weights; a node on a grid node keeps that node alone) and shares those grid
  /// nodes with the MPM side. Collective; at a window's start.
  void place_interface();
  /// grid_fe_share from the spread and the interface nodes' masses.
  void spread_interface_masses();
  /// The interface nodes' momentum spread on the grid with velocities `v` (by key), each
  /// node's field affine about it with interface_gradient.
  std::vector<mpm::Vector3> spread_interface_momentum(const std::vector<mpm::Vector3>& v) const;
  /// interface_gradient, from the FE ranks owning the nodes.
  void gather_interface_gradients();
  /// predict_interface for a following interface: the interface nodes move by their own
  /// forces over the far field's step fe_dt, the MPM grid nodes by theirs over the MPM step
  /// mpm_dt; the two velocity fields stick at every shared grid node (each takes the node's
  /// centre-of-mass velocity) and the interface nodes take their field's change back like
  /// FLIP, so momentum is exchanged exactly.
  void predict_following(double fe_dt, double mpm_dt, const mpm::SharedNodeState& mpm_side);
  /// A later substep of a window: the MPM grid nodes move by their own forces and stick to
  /// the interface's velocity over the window (its far field has stepped already); what that
  /// takes is booked and handed to the interface in the next window.
  void stick_to_interface(double dt, const mpm::SharedNodeState& mpm_side);
  /// book_mpm_side over the grid nodes, the reactions handed to the interface nodes in
  /// proportion to their mass there.
  void book_mpm_side_following(double dt, const mpm::SharedNodeState& mpm_side,
                               const std::vector<mpm::Vector3>& v_start,
                               const std::vector<mpm::Vector3>& v_end);
  void exchange_following(double time, double dt, const mpm::SharedNodeState& mpm_side,
                          std::vector<mpm::Vector3>& v_start, std::vector<mpm::Vector3>& v_end);

  HybridScene split;
  std::unique_ptr<mpm::Solver> mpm_solver;
  std::unique_ptr<fem::FarFieldSolver> fe_solver;
  std::vector<std::int64_t> keys;         ///< every interface node's grid key, sorted
  std::vector<std::size_t> fe_node_index; ///< position in keys of each FE interface node owned here
  std::vector<double> fe_mass;            ///< lumped FE mass of each key, kg
  /// 1 for every free component of each key's node, 0 where a grid-face support holds it.
  std::vector<mpm::Vector3> free_components;
  std::size_t fe_nodes_on_other_mpm_ranks = 0;
  InterfaceLedger book;
  // Following interface: the grid nodes shared (sorted keys) and each interface node's
  // weights on them, rows spread_begin[k] to spread_begin[k + 1] of spread_node and
  // spread_weight; the shared grid nodes' velocities at the window's start and end.
  std::vector<std::int64_t> grid_keys;
  std::vector<std::uint32_t> spread_begin, spread_node;
  std::vector<double> spread_weight;
  std::vector<double> grid_fe_share; ///< the interface nodes' mass spread on each, kg
  /// Each interface node's position when the window opened, m, and its far-field velocity
  /// gradient dv/dx then, 1/s: its velocity field is spread on the grid, affine about it.
  std::vector<mpm::Vector3> interface_position;
  std::vector<Eigen::Matrix3d> interface_gradient;
  std::vector<mpm::Vector3> grid_velocity_start, grid_velocity_end;

  // Multi-step window.
  double window_start = 0.0;
  double window_end = 0.0;
  bool window_open = false;
  std::vector<mpm::Vector3> velocity_start; ///< FE interface velocity at the window start
  std::vector<mpm::Vector3> velocity_end;   ///< at the window end (or over it, staggered)
  std::vector<mpm::Vector3> fe_velocity, fe_force; ///< FE interface state, by key
  std::vector<mpm::Vector3> created;    ///< momentum the current window created, by key
  std::vector<mpm::Vector3> correction; ///< impulse applied in the current window, by key
  std::vector<dealii::Tensor<1, 3>> targets;
  // Balanced windows (implicit far field).
  std::string fe_state_at_window_start;
  std::vector<mpm::Vector3> fe_window_impulse;  ///< of the far field's step, not yet booked
  std::vector<mpm::Vector3> interface_now; ///< shared nodes' velocity after the last substep
  /// The far field's effective interface mass, 3 per key, kg (sparse when probed).
  Eigen::SparseMatrix<double> balance_matrix;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> balance_solver;
  std::vector<double> balance_mpm_mass; ///< the MPM masses balance_solver was factored with
  // Dashpot windows: the far field's mean free interface velocity over the window, its
  // effective interface mass alone factored, and with the MPM masses times window / dt.
  std::vector<mpm::Vector3> dashpot_free_velocity;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> balance_free_solver;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> dashpot_solver;
  double dashpot_ratio = 0.0;        ///< window / dt dashpot_solver was factored with
  std::vector<double> dashpot_mass;  ///< and the MPM masses
  /// The work of each side on the interface when this window opened, J.
  double mpm_work_at_window_start = 0.0;
  double fe_work_at_window_start = 0.0;
  double largest_window_work = 0.0; ///< the most work that crossed the interface in one window, J
  /// Dashpot windows that create energy beyond this share of largest_window_work, or
  /// leave more than this share of the interface's momentum scale unmet, are halved.
  static constexpr double window_energy_tolerance = 0.01;
  static constexpr double window_residual_tolerance = 1e-3;
  double balance_window_length = 0.0; ///< s
  std::size_t exact_balance_limit = 750;
  double balance_scale = 0.0; ///< largest (m_fe + m_mpm) |v| of an interface node so far, kg m/s
  /// The far field's Newton solves to about 1e-8 of its force scale, so its transmitted
  /// impulse, and the balance, are not exact below about this; what is left is taken back in
  /// the next window (the momentum correction).
  static constexpr double balance_tolerance = 1e-9;
  static constexpr unsigned int max_balance_iterations = 8;

  MPI_Comm comm;
  std::function<void(fem::FarFieldSolver&)> prepare_far_field;
  std::vector<ZoneConversion> zone_conversions;
  std::uint64_t n_cells_beyond_limit = 0;
  /// The zone the deck starts with (a restart builds it again before it converts).
  std::array<double, 3> start_zone_min{{0.0, 0.0, 0.0}}, start_zone_max{{0.0, 0.0, 0.0}};
  std::uint64_t last_zone_check = 0; ///< MPM step of the last check
  double check_seconds = 0.0;
  bool retired = false;
  /// The impulse in transit when the far field retired (no interface node left to take it
  /// back through), kg m/s: it stays in the momentum ledger.
  mpm::Vector3 impulse_left_by_retirement = mpm::Vector3::Zero();
};
} // namespace vulnus::coupling
