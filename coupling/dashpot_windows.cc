// Dashpot windows for an implicit far field (Hybrid/Window coupling = dashpot; docs/far_field.md,
// section 1). Per window of length T:
//   1. the far field's free step (its interface nodes receive no impulse) gives its interface
//      end velocity v_free; V = (v_start + v_free) / 2 is its mean free velocity;
//   2. every MPM substep dt finds the shared nodes' mid-step velocity w from the MPM kick
//      w = v_0 + dt/2 (f + l) / m and the far field seen as V plus a dashpot of its effective
//      interface mass M (the inverse of its interface compliance over T): l = 2/T M (V - w), so
//        (M + T/dt m) (w - V) = T/dt m (v_0 - V) + T/2 f;
//   3. the last substep steps the far field from the window's start with minus the impulse
//      sum(dt l) the MPM side took (plus the correction left from the last window).
// Momentum is exchanged exactly; the interface's energy change over a window is
// -(T/2) sum dt (l - l_mean) M^-1 (l - l_mean) <= 0, so the coupling is stable for any T: it
// dissipates the part of the interface force that varies within a window.
#include "coupling/hybrid_solver.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <limits>

namespace vulnus::coupling
{
void HybridSolver::factor_dashpot(const double ratio, const std::vector<double>& mpm_mass)
{
  std::vector<double> scaled(mpm_mass.size());
  for (std::size_t k = 0; k < mpm_mass.size(); ++k)
    scaled[k] = ratio * mpm_mass[k];
  factor_effective_mass(scaled, dashpot_solver);
  dashpot_ratio = ratio;
  dashpot_mass = mpm_mass;
}

double HybridSolver::step_fe_to_impulse(const double window, const std::vector<mpm::Vector3>& target)
{
  const std::vector<mpm::Vector3>& free = free_components;
  auto residual = [&](Eigen::VectorXd& g)
  {
    g.resize(3 * static_cast<Eigen::Index>(keys.size()));
    double largest = 0.0;
    for (std::size_t k = 0; k < keys.size(); ++k)
    {
      const mpm::Vector3 gk = (fe_window_impulse[k] - target[k]).cwiseProduct(free[k]);
      g.segment<3>(3 * static_cast<Eigen::Index>(k)) = gk;
      largest = std::max(largest, gk.cwiseAbs().maxCoeff());
    }
    return largest;
  };
  return chord_iterate(window, balance_free_solver, window_balance_tolerance(window, {}),
                       residual);
}

bool HybridSolver::halve_dashpot_windows(const double window, const double dt)
{
  const double shortest = std::max(fe_solver->shortest_wave_transit(), dt);
  if (window <= shortest * (1.0 + 1e-9))
    return false;
  book.dashpot_window_limit = std::max(0.5 * window, shortest);
  ++book.windows_halved;
  return true;
}

void HybridSolver::dashpot_free_step(const mpm::SharedNodeState& mpm_side, const double dt)
{
  const std::size_t n = keys.size();
  for (;;)
  {
    const double window = window_end - window_start;
    // The dashpot must be no softer than the far field over this window: a matrix built for a
    // longer window (a larger effective mass) is rebuilt, one for a somewhat shorter is kept.
    if (static_cast<std::size_t>(balance_matrix.rows()) != 3 * n ||
        window > 1.25 * balance_window_length || window < (1.0 - 1e-6) * balance_window_length)
    {
      build_balance_matrix(window);
      factor_effective_mass(std::vector<double>(n, 0.0), balance_free_solver);
    }
    // The free step: no impulse on the far field's interface nodes, from the guess that its
    // interface keeps its velocity for about two wave transits of the smallest cell and then
    // stands (its mean over the window V = keep v_start): a window of many transits would
    // otherwise drive it by many cells, beyond what the far field's Newton step comes back
    // from (200 transits: 4 mm on a 12 mm block). The summed-mass prediction moves it further.
    const double keep = std::min(1.0, 2.0 * fe_solver->shortest_wave_transit() / window);
    for (std::size_t k = 0; k < n; ++k)
      velocity_end[k] = (2.0 * keep - 1.0) * velocity_start[k];
    bool taken = false;
    std::exception_ptr failure;
    try
    {
      fe_window_impulse = step_fe(window);
      taken = step_fe_to_impulse(window, std::vector<mpm::Vector3>(n, mpm::Vector3::Zero())) <=
              window_residual_tolerance;
    }
    catch (const std::runtime_error&)
    {
      failure = std::current_exception();
    }
    if (taken)
      break;
    if (!halve_dashpot_windows(window, dt))
    {
      // As short as a window may be: a failed step stops the run, an unmet free end is
      // carried like any unbalanced window's.
      if (failure)
        std::rethrow_exception(failure);
      break;
    }
    // Again over the shorter window, from the far field's state at its start.
    window_end = window_start + book.dashpot_window_limit;
    std::istringstream state(fe_state_at_window_start);
    fe_solver->restore(state);
    predict_interface(window_end - window_start, mpm_side);
  }
  dashpot_free_velocity.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    dashpot_free_velocity[k] = 0.5 * (velocity_start[k] + velocity_end[k]);
}

void HybridSolver::check_dashpot_window(const double residual)
{
  // What the MPM side gave the interface in this window and what the far field received: the
  // window may dissipate, not create (exact for a far field that answers as its effective
  // mass says; a probed mass off over many transits, or a far field that yields, breaks it).
  const double given = book.mpm_work - mpm_work_at_window_start;
  const double received = book.fe_work - fe_work_at_window_start;
  const double created = received - given;
  const double crossed = std::max(std::abs(given), std::abs(received));
  // Judged against the most any window has carried: a quiet window's round-off is no cause.
  largest_window_work = std::max(largest_window_work, crossed);
  const double window = window_end - window_start;
  if (residual > window_residual_tolerance ||
      created > window_energy_tolerance * largest_window_work)
    halve_dashpot_windows(window, 0.0);
}

void HybridSolver::exchange_dashpot(const double time, const double dt, const bool first_substep,
                                    const mpm::SharedNodeState& mpm_side,
                                    std::vector<mpm::Vector3>& v_start,
                                    std::vector<mpm::Vector3>& v_end)
{
  const std::size_t n = keys.size();
  const std::vector<mpm::Vector3>& free = free_components;
  if (first_substep)
  {
    open_implicit_window(window_end - window_start, mpm_side);
    mpm_work_at_window_start = book.mpm_work;
    fe_work_at_window_start = book.fe_work;
    dashpot_free_step(mpm_side, dt);
    if (interface_now.size() != n)
      interface_now = velocity_start;
  }
  // The free step may have shortened this window: its last substep is the one that reaches
  // the new end.
  const double window = window_end - window_start;
  const double ratio = window / dt;
  const bool last_substep = time + dt >= window_end - 1e-9 * window;
  if (first_substep)
    factor_dashpot(ratio, mpm_side.mass);
  v_start = interface_now;
  const std::vector<mpm::Vector3>& mean_free = dashpot_free_velocity;
  // A substep much shorter or longer than the factored one (the window's last) is factored
  // anew: the refinement below converges for diagonals within about 10 %.
  if (std::abs(ratio - dashpot_ratio) > 0.1 * dashpot_ratio)
    factor_dashpot(ratio, mpm_side.mass);

  // (M + T/dt m) x = T/dt m (v_0 - V) + T/2 f with x = w - V, solved with the factorization of
  // the window's first substep refined for this substep's masses and ratio.
  Eigen::VectorXd rhs(3 * n), x = Eigen::VectorXd::Zero(3 * n), r(3 * n), product(3 * n);
  for (std::size_t k = 0; k < n; ++k)
    rhs.segment<3>(3 * static_cast<Eigen::Index>(k)) =
        (ratio * mpm_side.mass[k] * (v_start[k] - mean_free[k]) + 0.5 * window * mpm_side.force[k])
            .cwiseProduct(free[k]);
  const double rhs_norm = rhs.cwiseAbs().maxCoeff();
  double last_residual = std::numeric_limits<double>::infinity();
  bool refactored = false;
  for (unsigned int iteration = 0; iteration < 50; ++iteration)
  {
    product.noalias() = balance_matrix * x;
    for (std::size_t k = 0; k < n; ++k)
      for (unsigned int c = 0; c < 3; ++c)
      {
        const Eigen::Index i = 3 * static_cast<Eigen::Index>(k) + c;
        r[i] = free[k][c] == 0.0 ? 0.0 : rhs[i] - product[i] - ratio * mpm_side.mass[k] * x[i];
      }
    const double residual = r.cwiseAbs().maxCoeff();
    if (!(residual > 1e-13 * rhs_norm))
      break;
    if (residual > 0.5 * last_residual && !refactored)
    {
      // The masses moved too far from the factored ones (points reached a node).
      factor_dashpot(ratio, mpm_side.mass);
      refactored = true;
    }
    last_residual = residual;
    x += dashpot_solver.solve(r);
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const mpm::Vector3 w =
        mean_free[k] + x.segment<3>(3 * static_cast<Eigen::Index>(k)).cwiseProduct(free[k]);
    v_end[k] = mpm_side.mass[k] > 0.0 ? mpm::Vector3(2.0 * w - v_start[k]) : w;
    v_end[k] = v_end[k].cwiseProduct(free[k]);
  }
  interface_now = v_end;
  book_mpm_side(dt, mpm_side, v_start, v_end);

  if (last_substep)
  {
    // The far field takes what the MPM side gave, and the correction the window applies.
    std::vector<mpm::Vector3> target(n);
    for (std::size_t k = 0; k < n; ++k)
      target[k] = correction[k] - created[k];
    const double residual = step_fe_to_impulse(window, target);
    book_fe_side(fe_window_impulse);
    fe_state_at_window_start.clear();
    check_dashpot_window(residual);
  }
}
} // namespace vulnus::coupling
