// Balanced multi-step windows for an implicit far field (docs/far_field.md, section 1): the
// far field steps once per window, driven by the interface's end velocities; the MPM substeps
// move the interface towards the end velocities that would balance the window's momentum, and
// the last substep balances it exactly, re-stepping the far field from the window's start.
#include "coupling/hybrid_solver.h"

#include <array>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <unordered_map>
#include <cmath>
#include <sstream>

namespace vulnus::coupling
{
bool HybridSolver::balances_windows() const
{
  return split.hybrid.scheme == CouplingScheme::multi_step &&
         (split.fe.integrator == fem::TimeIntegrator::newmark ||
          split.fe.integrator == fem::TimeIntegrator::generalized_alpha);
}

void HybridSolver::exchange_balanced(const double time, const double dt, const bool first_substep,
                                     const bool last_substep, const mpm::SharedNodeState& mpm_side,
                                     std::vector<mpm::Vector3>& v_start,
                                     std::vector<mpm::Vector3>& v_end)
{
  const double window = window_end - window_start;
  const std::size_t n = keys.size();
  if (first_substep)
  {
    open_implicit_window(window, mpm_side);
    fe_window_impulse = step_fe(window);
    interface_now = velocity_start;
    if (static_cast<std::size_t>(balance_matrix.rows()) != 3 * n ||
        std::abs(window - balance_window_length) > 0.25 * window)
      build_balance_matrix(window);
    factor_balance_matrix(mpm_side.mass);
  }
  v_start = interface_now;
  if (last_substep)
  {
    balance_window(window, dt, mpm_side, v_start);
    v_end = velocity_end;
    book_fe_side(fe_window_impulse);
    fe_state_at_window_start.clear();
  }
  else
  {
    // The end velocities that would balance the window if this substep's MPM force held to
    // its end (one chord step from the far field's step), and this substep's share of the way
    // to them along the window.
    Eigen::VectorXd g;
    creation_residual(mpm_side, v_start, window_end - time, g);
    const Eigen::VectorXd dv = balance_solver.solve(g);
    const std::vector<mpm::Vector3>& free = free_components;
    const double s1 = (time + dt - window_start) / window;
    for (std::size_t k = 0; k < n; ++k)
    {
      const mpm::Vector3 estimate = velocity_end[k] - dv.segment<3>(3 * k).cwiseProduct(free[k]);
      v_end[k] = velocity_start[k] + s1 * (estimate - velocity_start[k]);
    }
  }
  interface_now = v_end;
  book_mpm_side(dt, mpm_side, v_start, v_end);
}

void HybridSolver::open_implicit_window(const double window, const mpm::SharedNodeState& mpm_side)
{
  start_window_correction();
  predict_interface(window, mpm_side);
  std::ostringstream state;
  fe_solver->save(state);
  fe_state_at_window_start = state.str();
  // Until the far field's step succeeds it stands at the window's start and has received
  // nothing (a run stopped by a failed step counts its momentum so).
  fe_window_impulse.assign(keys.size(), mpm::Vector3::Zero());
}

double HybridSolver::creation_residual(const mpm::SharedNodeState& mpm_side,
                                       const std::vector<mpm::Vector3>& v_start,
                                       const double remaining, Eigen::VectorXd& g) const
{
  // Momentum the window creates at each shared node if its end velocity is velocity_end and
  // this substep's MPM force holds for the time remaining: the far field's share (from its
  // step driven by velocity_end), the MPM substeps' so far (created), the MPM side's from now
  // to the end, less the correction the window is to apply. Components a support holds are
  // left out.
  const std::vector<mpm::Vector3>& free = free_components;
  g.resize(3 * keys.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    const mpm::Vector3 gk =
        (fe_window_impulse[k] + created[k] - correction[k] +
         mpm_side.mass[k] * (velocity_end[k] - v_start[k]) - remaining * mpm_side.force[k])
            .cwiseProduct(free[k]);
    g.segment<3>(3 * k) = gk;
    largest = std::max(largest, gk.cwiseAbs().maxCoeff());
  }
  return largest;
}

void HybridSolver::interface_response(const std::vector<double>& fe_dofs,
                                      const std::vector<std::size_t>& probe, const double factor,
                                      std::vector<double>& response) const
{
  std::vector<dealii::types::global_dof_index> dofs;
  for (const std::size_t j : probe)
    dofs.push_back(static_cast<dealii::types::global_dof_index>(fe_dofs[j]));
  const std::vector<dealii::Tensor<1, 3>> forces = fe_solver->interface_stiffness_response(dofs);
  std::fill(response.begin(), response.end(), 0.0);
  for (std::size_t i = 0; i < forces.size(); ++i)
    for (unsigned int c = 0; c < 3; ++c)
      response[3 * fe_node_index[i] + c] = factor * forces[i][c];
  mpm_solver->rank_group().sum(response.data(), static_cast<int>(response.size()));
}

void HybridSolver::build_balance_matrix(const double window)
{
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = 3 * keys.size();
  std::vector<double> dofs(n, 0.0);
  const std::vector<fem::NodeRecord>& nodes = fe_solver->interface_nodes();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (unsigned int c = 0; c < 3; ++c)
      dofs[3 * fe_node_index[i] + c] = static_cast<double>(nodes[i].dofs[c]);
  mpm_solver->rank_group().sum(dofs.data(), static_cast<int>(n));
  const std::vector<mpm::Vector3>& free = free_components;
  const double factor = fe_solver->interface_mass_factor(window);

  fe_solver->prepare_interface_stiffness(window);
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> response(n);
  if (n <= exact_balance_limit)
  {
    for (std::size_t j = 0; j < n; ++j)
    {
      if (free[j / 3][j % 3] == 0.0)
        continue;
      interface_response(dofs, {j}, factor, response);
      for (std::size_t i = 0; i < n; ++i)
        if (response[i] != 0.0)
          entries.emplace_back(static_cast<int>(i), static_cast<int>(j), response[i]);
    }
  }
  else
  {
    // Probing: one solve moves every free dof of one component at the nodes whose grid
    // indices have one residue modulo probe_period; the forces within probe_reach nodes of
    // such a node are its column's (the far field's answer to a window's displacement decays
    // within a few cells while a window lasts about a wave's transit of one), what lies
    // farther is dropped.
    const mpm::Grid& grid = mpm_solver->background_grid();
    auto residue = [](const int i) { return ((i % probe_period) + probe_period) % probe_period; };
    std::unordered_map<std::int64_t, std::size_t> index_of_key;
    std::vector<std::array<int, 3>> ijk(keys.size()), residues(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k)
    {
      index_of_key.emplace(keys[k], k);
      ijk[k] = grid.node_ijk(keys[k]);
      for (int d = 0; d < 3; ++d)
        residues[k][d] = residue(ijk[k][d]);
    }
    std::vector<std::size_t> probe;
    for (int r0 = 0; r0 < probe_period; ++r0)
      for (int r1 = 0; r1 < probe_period; ++r1)
        for (int r2 = 0; r2 < probe_period; ++r2)
          for (unsigned int c = 0; c < 3; ++c)
          {
            const std::array<int, 3> wanted = {r0, r1, r2};
            probe.clear();
            for (std::size_t k = 0; k < keys.size(); ++k)
              if (free[k][c] != 0.0 && residues[k] == wanted)
                probe.push_back(3 * k + c);
            if (probe.empty())
              continue;
            interface_response(dofs, probe, factor, response);
            for (std::size_t k = 0; k < keys.size(); ++k)
            {
              // The probed node nearest k: per axis the wanted residue's offset, taken in
              // [-probe_reach, probe_reach] (probe_period = 2 probe_reach + 1).
              std::array<int, 3> at = ijk[k];
              for (int d = 0; d < 3; ++d)
              {
                const int offset = residue(wanted[d] - ijk[k][d]);
                at[d] += offset > probe_reach ? offset - probe_period : offset;
              }
              const auto found = index_of_key.find(grid.node_key(at[0], at[1], at[2]));
              if (found == index_of_key.end() || free[found->second][c] == 0.0)
                continue;
              for (unsigned int ci = 0; ci < 3; ++ci)
                if (response[3 * k + ci] != 0.0)
                  entries.emplace_back(static_cast<int>(3 * k + ci),
                                       static_cast<int>(3 * found->second + c),
                                       response[3 * k + ci]);
            }
          }
  }
  balance_matrix.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  balance_matrix.setFromTriplets(entries.begin(), entries.end());
  fe_solver->release_interface_stiffness();
  balance_window_length = window;
  ++book.balance_matrices;
  book.balance_matrix_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void HybridSolver::factor_effective_mass(const std::vector<double>& diagonal,
                                         Eigen::SparseLU<Eigen::SparseMatrix<double>>& solver) const
{
  const std::vector<mpm::Vector3>& free = free_components;
  auto held = [&](const Eigen::Index i) { return free[i / 3][i % 3] == 0.0; };
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(balance_matrix.nonZeros() + balance_matrix.rows()));
  for (Eigen::Index j = 0; j < balance_matrix.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(balance_matrix, j); it; ++it)
      if (!held(it.row()) && !held(it.col()))
        entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
  for (Eigen::Index i = 0; i < balance_matrix.rows(); ++i)
    entries.emplace_back(static_cast<int>(i), static_cast<int>(i), held(i) ? 1.0 : diagonal[i / 3]);
  Eigen::SparseMatrix<double> a(balance_matrix.rows(), balance_matrix.cols());
  a.setFromTriplets(entries.begin(), entries.end());
  solver.compute(a);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("balanced window: the interface's effective-mass matrix could not "
                             "be factored (" + solver.lastErrorMessage() +
                             "); use Far field/Integrator = central difference");
}

void HybridSolver::factor_balance_matrix(const std::vector<double>& mpm_mass)
{
  factor_effective_mass(mpm_mass, balance_solver);
  balance_mpm_mass = mpm_mass;
}

double HybridSolver::window_balance_tolerance(const double window,
                                              const std::vector<double>& mpm_mass)
{
  // Relative to the largest momentum the interface has carried (tiny waves ahead of a pulse
  // need no finer balance), and no finer than the velocities the far field's Newton resolves
  // (it stops at corrections of 1e-12 of a cell): 1e-10 of a cell per window.
  double scale = 0.0, largest_mass = 0.0;
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    const double mass = fe_mass[k] + (mpm_mass.empty() ? 0.0 : mpm_mass[k]);
    scale = std::max(scale, mass * std::max(velocity_end[k].norm(), velocity_start[k].norm()));
    largest_mass = std::max(largest_mass, mass);
  }
  balance_scale = std::max(balance_scale, scale);
  return std::max(balance_tolerance * balance_scale,
                  1e-10 * largest_mass * split.fe.interface_cell_size / window);
}

double HybridSolver::chord_iterate(const double window,
                                 const Eigen::SparseLU<Eigen::SparseMatrix<double>>& solver,
                                 const double tolerance,
                                 const std::function<double(Eigen::VectorXd&)>& residual)
{
  const std::vector<mpm::Vector3>& free = free_components;
  auto restep = [&]
  {
    std::istringstream state(fe_state_at_window_start);
    fe_solver->restore(state);
    fe_window_impulse = step_fe(window);
  };
  Eigen::VectorXd g;
  double largest = residual(g);
  // A probed effective mass that is off (a window of many wave transits) makes the iteration
  // wander: the far field is left at the best guess it met, not at the last.
  double best = largest;
  std::vector<mpm::Vector3> best_guess = velocity_end;
  bool at_best = true;
  unsigned int iteration = 0;
  for (; largest > tolerance && iteration < max_balance_iterations; ++iteration)
  {
    const Eigen::VectorXd dv = solver.solve(g);
    for (std::size_t k = 0; k < keys.size(); ++k)
      velocity_end[k] -= dv.segment<3>(3 * static_cast<Eigen::Index>(k)).cwiseProduct(free[k]);
    try
    {
      restep();
    }
    catch (const std::runtime_error&)
    {
      // The guess crushed far-field cells (its Newton step failed on every rank alike).
      at_best = false;
      ++iteration;
      break;
    }
    largest = residual(g);
    at_best = largest < best;
    if (at_best)
    {
      best = largest;
      best_guess = velocity_end;
    }
  }
  book.balance_solves += iteration;
  if (!at_best)
  {
    velocity_end = best_guess;
    restep();
    largest = residual(g);
    ++book.balance_solves;
  }
  if (largest <= tolerance)
    return 0.0;
  ++book.balance_unconverged_windows;
  // Relative to the interface's momentum scale, or (an interface still at rest) to the scale
  // whose share the tolerance's floor is.
  const double left = largest / std::max(balance_scale, tolerance / balance_tolerance);
  book.largest_balance_residual = std::max(book.largest_balance_residual, left);
  return left;
}

void HybridSolver::balance_window(const double window, const double dt,
                                  const mpm::SharedNodeState& mpm_side,
                                  const std::vector<mpm::Vector3>& v_start)
{
  // Newton's chord iteration on the momentum the window creates (creation_residual with the
  // last substep's dt): the matrix is the MPM masses plus the far field's effective interface
  // mass over the window, each guess is evaluated by the far field's step from the window's
  // start.
  chord_iterate(window, balance_solver, window_balance_tolerance(window, mpm_side.mass),
                [&](Eigen::VectorXd& g) { return creation_residual(mpm_side, v_start, dt, g); });
}
} // namespace vulnus::coupling
