// Running account of what crosses the MPM-FE interface: work done by each side on it and the
// momentum each side received (docs/DESIGN.md section 6, the interface energy error).
#pragma once

#include <Eigen/Core>

namespace vulnus::coupling
{
struct InterfaceLedger
{
  /// Work the MPM side did on the interface since the start, J: sum over MPM steps of
  /// -R . v_end dt, R = m_mpm (v_end - v_start)/dt - f_mpm the force the interface exerts on
  /// the MPM side of the shared nodes.
  double mpm_work = 0.0;
  /// Work the FE side received through the interface, J: on the FE share of the nodes
  /// m_fe (v_end - v_start) . v_end at every MPM step, on the rest of the body minus the
  /// transmitted impulse times the node's mean velocity over every FE step.
  double fe_work = 0.0;
  /// Momentum the interface gave the MPM side and the FE side since the start, kg m/s; their
  /// sum plus HybridSolver::impulse_in_transit is the momentum the coupling created (zero to
  /// round-off).
  Eigen::Vector3d mpm_impulse = Eigen::Vector3d::Zero();
  Eigen::Vector3d fe_impulse = Eigen::Vector3d::Zero();
  unsigned long fe_steps = 0;
  /// Balanced windows (implicit far field): far-field steps repeated to close the windows'
  /// momentum balance; windows whose balance stopped above its tolerance (what is left is
  /// taken back in the next window) and the largest residual left, relative to the
  /// interface's momentum scale; the effective-mass matrices built and their wall time.
  unsigned long balance_solves = 0;
  unsigned long balance_unconverged_windows = 0;
  double largest_balance_residual = 0.0;
  unsigned long balance_matrices = 0;
  double balance_matrix_seconds = 0.0;
  /// Implicit windows shortened to one wave transit of the far field's smallest cell (the
  /// deck asked for longer ones), and the shortest such limit met, s.
  unsigned long windows_shortened = 0;
  double shortest_window_limit = 0.0;
  /// Dashpot windows halved because the far field could not take one (its step failed or its
  /// impulse was left unmet) or one created energy, and the longest window from then on, s
  /// (0: the deck's; it only shrinks).
  unsigned long windows_halved = 0;
  double dashpot_window_limit = 0.0;
  unsigned long mpm_steps = 0;

  /// Work done by MPM minus work received by FE (the interface energy error), J.
  double energy_error() const { return mpm_work - fe_work; }
};
} // namespace vulnus::coupling
