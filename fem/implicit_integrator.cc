// Implicit step: Newmark average acceleration or generalized-alpha (Chung & Hulbert 1993,
// J. Appl. Mech. 60:371-375, eqs. 25 and 27), Newton with the consistent tangent dP/dF of the
// material, Trilinos CG/GMRES with ML algebraic multigrid (translations as near-null space).
//   residual  r(u) = f_ext(t_{n+1-af}) - f_int(u_{n+1-af}) - M a_{n+1-am}   (consistent M)
//   tangent   -dr/du = (1 - af) K_t + (1 - am) / (beta dt^2) M
// A step longer than two wave transits of the smallest cell starts Newton from the last
// converged state, and its first correction carries the Dirichlet dofs' motion as
// inhomogeneous constraints (spread through the tangent), instead of extrapolating the
// acceleration: over many transits the extrapolated state is far from the answer (strains of
// order v dt / h), and Newton from there fails, while a Dirichlet motion put into its dofs alone
// crushes the cells next to them and makes the tangent indefinite.
#include "fem/cell_stiffness.h"
#include "fem/far_field_data.h"
#include "fem/ordered_cell_loop.h"
#include "fem/tensor_conversion.h"

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <limits>
#include <memory>
#include <cmath>
#include <sstream>

namespace vulnus::fem
{
using namespace dealii;

struct ImplicitData
{
  TrilinosWrappers::SparseMatrix matrix;
  TrilinosWrappers::PreconditionAMG preconditioner;
  /// The hierarchy's step length (0: none built) and the Krylov iterations of the first
  /// solve after it was built.
  double preconditioner_dt = 0.0;
  unsigned int iterations_after_setup = 0;
  unsigned int last_iterations = 0;
  bool first_solve_after_setup = false;
  std::vector<std::vector<bool>> constant_modes;
  TrilinosWrappers::MPI::Vector rhs, increment, external_condensed;
  TrilinosWrappers::MPI::Vector u_old, v_old, a_old;
  TrilinosWrappers::MPI::Vector u_alpha, a_alpha; ///< ghosted
  /// A long step's first correction: the increment constraints with the Dirichlet dofs'
  /// motion over the step as inhomogeneities.
  AffineConstraints<double> lift_constraints;
};

namespace
{
struct AlphaCoefficients
{
  double alpha_m = 0.0, alpha_f = 0.0, beta = 0.25, gamma = 0.5;
};

AlphaCoefficients coefficients(const FeSceneParameters& prm)
{
  AlphaCoefficients c;
  if (prm.integrator == TimeIntegrator::generalized_alpha)
  {
    const double rho = prm.spectral_radius;
    c.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
    c.alpha_f = rho / (rho + 1.0);
    c.gamma = 0.5 - c.alpha_m + c.alpha_f;
    c.beta = 0.25 * (1.0 - c.alpha_m + c.alpha_f) * (1.0 - c.alpha_m + c.alpha_f);
  }
  return c;
}

} // namespace

double integrator_gamma(const FeSceneParameters& prm) { return coefficients(prm).gamma; }
double implicit_beta(const FeSceneParameters& prm) { return coefficients(prm).beta; }
double implicit_alpha_m(const FeSceneParameters& prm) { return coefficients(prm).alpha_m; }
double implicit_alpha_f(const FeSceneParameters& prm) { return coefficients(prm).alpha_f; }

void forget_implicit_preconditioner(FarFieldSolver::Data& d)
{
  if (d.implicit)
    d.implicit->preconditioner_dt = 0.0;
}

namespace
{
void initialize_implicit(FarFieldSolver::Data& d)
{
  d.implicit = std::make_shared<ImplicitData>();
  ImplicitData& im = *d.implicit;
  TrilinosWrappers::SparsityPattern sparsity(d.owned_dofs, d.owned_dofs, d.relevant_dofs, d.comm);
  DoFTools::make_sparsity_pattern(d.dof_handler, sparsity, d.increment_constraints, false,
                                  Utilities::MPI::this_mpi_process(d.comm));
  sparsity.compress();
  im.matrix.reinit(sparsity);
  DoFTools::extract_constant_modes(d.dof_handler, ComponentMask(), im.constant_modes);
  for (TrilinosWrappers::MPI::Vector* v :
       {&im.rhs, &im.increment, &im.external_condensed, &im.u_old, &im.v_old, &im.a_old})
    v->reinit(d.owned_dofs, d.comm);
  im.u_alpha.reinit(d.owned_dofs, d.relevant_dofs, d.comm);
  im.a_alpha.reinit(d.owned_dofs, d.relevant_dofs, d.comm);
}

/// One live cell's share of the Newton system, computed on a thread and added in cell order.
struct NewtonCell
{
  std::vector<types::global_dof_index> dofs;
  FullMatrix<double> matrix;
  dealii::Vector<double> rhs;
  std::vector<double> internal_force, inertia;
  double strain_energy = 0.0, dissipated = 0.0;
};

/// A thread's tools for one chunk of cells.
struct NewtonCellWorker
{
  NewtonCellWorker(const FarFieldSolver::Data& d)
    : fe_values(d.mapping, d.fe, d.quadrature,
                update_values | update_gradients | update_JxW_values),
      values(d.fe.n_dofs_per_cell()), u_local(d.fe.n_dofs_per_cell()),
      a_local(d.fe.n_dofs_per_cell())
  {
  }
  FEValues<3> fe_values;
  CellStiffness law;
  std::vector<double> values, u_local, a_local;
};

/// Cell c's matrix (mass_factor M + stiffness_factor K_t), right-hand side -(f_int + M a),
/// forces and energies at u_alpha, a_alpha; its trial states, stress, failure and wave speed.
/// Throws std::runtime_error where the law refuses a point.
void compute_newton_cell(FarFieldSolver::Data& d, const std::vector<unsigned int>& component,
                         const double mass_factor, const double stiffness_factor,
                         const materials::FailureParameters* criterion, NewtonCellWorker& w,
                         const long c, NewtonCell& out)
{
  ImplicitData& im = *d.implicit;
  const unsigned int n_dofs = d.fe.n_dofs_per_cell();
  const auto& cell = d.live_cells[static_cast<std::size_t>(c)];
  const unsigned int k = cell->active_cell_index();
  const std::size_t first = std::size_t(k) * d.n_q_points;
  w.fe_values.reinit(cell);
  out.dofs.resize(n_dofs);
  cell->get_dof_indices(out.dofs);
  const double* u_values = im.u_alpha.trilinos_vector()[0];
  const double* a_values = im.a_alpha.trilinos_vector()[0];
  const int* local = &d.cell_local_dofs[std::size_t(k) * n_dofs];
  for (unsigned int i = 0; i < n_dofs; ++i)
  {
    w.u_local[i] = u_values[local[i]];
    w.a_local[i] = a_values[local[i]];
  }
  out.matrix.reinit(n_dofs, n_dofs);
  out.rhs.reinit(n_dofs);
  out.internal_force.assign(n_dofs, 0.0);
  out.inertia.assign(n_dofs, 0.0);
  out.strain_energy = out.dissipated = 0.0;
  Tensor<2, 3> stress_sum;
  double volume = 0.0, c_max = 0.0, proximity = 0.0;
  unsigned char flags = 0;
  materials::PointState* states = &d.trial_states[first];
  std::copy_n(&d.committed_states[first], d.n_q_points, states);
  try
  {
    w.law.evaluate(w.fe_values, component, w.u_local, *d.material, &d.fiber_directions[first],
                   states, d.prm.volume_averaging, d.material_time_step);
  }
  catch (const std::runtime_error& e)
  {
    throw std::runtime_error(std::string("FE implicit: ") + e.what());
  }
  const bool fibers = d.material->uses_fibers();
  for (unsigned int q = 0; q < d.n_q_points; ++q)
  {
    Tensor<1, 3> a_q;
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      w.values[i] = w.fe_values.shape_value_component(i, q, component[i]);
      a_q[component[i]] += w.a_local[i] * w.values[i];
    }
    const materials::PointResponse& response = w.law.responses[q];
    const double J = w.law.F_law[q].determinant();
    const double JxW = w.law.JxW[q];
    const double rho_JxW = d.prm.density * JxW;
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const unsigned int ci = component[i];
      out.inertia[i] += rho_JxW * w.values[i] * a_q[ci];
      out.rhs(i) -= rho_JxW * w.values[i] * a_q[ci];
      for (unsigned int j = 0; j < n_dofs; ++j)
        if (component[j] == ci)
          out.matrix(i, j) += mass_factor * rho_JxW * w.values[i] * w.values[j];
    }
    out.strain_energy += response.energy_density * JxW;
    out.dissipated += response.dissipated_density * JxW;
    stress_sum += JxW * to_dealii(response.cauchy_stress);
    volume += JxW;
    c_max = std::max(c_max, std::sqrt(response.p_wave_modulus * J / d.prm.density));
    flags |= states[q].failure;
    if (criterion != nullptr)
      proximity = std::max(proximity, failure_proximity(*criterion, w.law.F_law[q],
                                                        fibers ? &d.fiber_directions[first + q]
                                                               : nullptr,
                                                        states[q].failure,
                                                        d.prm.failure_proximity));
  }
  for (unsigned int i = 0; i < n_dofs; ++i)
  {
    const double f_int = w.law.force(i, component[i]);
    out.internal_force[i] += f_int;
    out.rhs(i) -= f_int;
    for (unsigned int j = 0; j < n_dofs; ++j)
      out.matrix(i, j) += stiffness_factor * w.law.stiffness(i, j);
  }
  d.cell_stress[k] = stress_sum / volume;
  d.cell_failure[k] = flags;
  d.cell_wave_speed[k] = c_max;
  if (criterion != nullptr)
    d.cell_failure_proximity[k] = proximity;
}

/// Assembles the Newton system at u_alpha, a_alpha into im.matrix and im.rhs (increment
/// constraints), f_int into internal_force_raw; updates trial states and cell data. The cells
/// are evaluated on the OpenMP threads and added in cell order (the same system on any
/// number of threads).
EvaluationSums assemble_newton_system(FarFieldSolver::Data& d, const double mass_factor,
                                      const double stiffness_factor,
                                      const AffineConstraints<double>& constraints)
{
  ImplicitData& im = *d.implicit;
  if (d.cell_local_dofs.empty())
    d.index_cell_dofs(im.u_alpha);
  const std::vector<unsigned int> component = dof_components(d.fe);
  const materials::FailureParameters* criterion = d.proximity_criterion();
  EvaluationSums sums;
  bool inverted = false;
  std::string message;

  im.matrix = 0.0;
  im.rhs = 0.0;
  d.internal_force_raw = 0.0;
  d.inertia_coupling_raw = 0.0;
  try
  {
    ordered_cell_loop<NewtonCell>(
      static_cast<long>(d.live_cells.size()), 32,
      [&]() { return std::make_unique<NewtonCellWorker>(d); },
      [&](NewtonCellWorker& w, const long c, NewtonCell& out)
      { compute_newton_cell(d, component, mass_factor, stiffness_factor, criterion, w, c, out); },
      [&](long, NewtonCell& cell)
      {
        sums.strain_energy += cell.strain_energy;
        sums.dissipated += cell.dissipated;
        d.internal_force_raw.add(cell.dofs, cell.internal_force);
        d.inertia_coupling_raw.add(cell.dofs, cell.inertia);
        constraints.distribute_local_to_global(cell.matrix, cell.rhs, cell.dofs, im.matrix,
                                               im.rhs);
      });
  }
  catch (const std::runtime_error& e)
  {
    inverted = true;
    message = e.what();
  }
  for (const auto dof : d.dead_dofs)
    im.matrix.add(dof, dof, mass_factor * d.dead_dof_mass);
  im.matrix.compress(VectorOperation::add);
  im.rhs.compress(VectorOperation::add);
  d.internal_force_raw.compress(VectorOperation::add);
  d.inertia_coupling_raw.compress(VectorOperation::add);
  // Consistent minus lumped inertia: (M a)_i - m_i a_i.
  for (const auto i : d.owned_dofs)
    d.inertia_coupling_raw(i) -= d.lumped_mass(i) * im.a_alpha(i);
  d.inertia_coupling_raw.compress(VectorOperation::insert);
  throw_if_any(inverted, message, d.comm);
  return sums;
}
} // namespace

namespace
{
/// External forces at t_{n+1-af}, condensed, zero on Dirichlet rows.
void assemble_condensed_external_forces(FarFieldSolver::Data& d, ImplicitData& im,
                                        const double t_alpha)
{
  im.external_condensed = 0.0;
  d.assemble_external_forces(t_alpha, &im.external_condensed);
  for (const DirichletDof& dirichlet : d.dirichlet_dofs)
    im.external_condensed(dirichlet.dof) = 0.0;
  im.external_condensed.compress(VectorOperation::insert);

}

/// im.lift_constraints: the hanging nodes, and every line of the increment constraints without
/// entries (Dirichlet and dead dofs) with its owner's value of `lift` as inhomogeneity.
void build_lift_constraints(FarFieldSolver::Data& d, ImplicitData& im,
                            const TrilinosWrappers::MPI::Vector& lift)
{
  TrilinosWrappers::MPI::Vector ghosted(d.owned_dofs, d.relevant_dofs, d.comm);
  ghosted = lift;
  AffineConstraints<double>& lc = im.lift_constraints;
  lc.clear();
  lc.reinit(d.relevant_dofs);
  lc.merge(d.hanging_constraints);
  for (const auto& line : d.increment_constraints.get_lines())
    if (line.entries.empty() && !lc.is_constrained(line.index))
    {
      lc.add_line(line.index);
      lc.set_inhomogeneity(line.index, ghosted(line.index));
    }
  lc.close();
}

/// Predictor a_{n+1} = a_n, or (a long step) u_{n+1} = u_n with the Dirichlet dofs' motion
/// in im.lift_constraints (`lifting`: whether they move at all); Dirichlet dofs from their
/// velocity at t_{n+1}. Returns the Dirichlet dofs' accelerations.
std::vector<double> predict_displacement(FarFieldSolver::Data& d, ImplicitData& im,
                                         const AlphaCoefficients& c, const double dt,
                                         const double t_new, const bool long_step, bool& lifting)
{
  lifting = false;
  if (!long_step)
    d.displacement.add(dt, im.v_old, 0.5 * dt * dt, im.a_old);
  TrilinosWrappers::MPI::Vector lift;
  if (long_step)
    lift.reinit(d.owned_dofs, d.comm);
  std::vector<double> a_dirichlet(d.dirichlet_dofs.size());
  for (std::size_t k = 0; k < d.dirichlet_dofs.size(); ++k)
  {
    const DirichletDof& dirichlet = d.dirichlet_dofs[k];
    const auto i = dirichlet.dof;
    const double v_new = d.dirichlet_velocity(dirichlet, t_new);
    a_dirichlet[k] = (v_new - im.v_old(i) - dt * (1.0 - c.gamma) * im.a_old(i)) / (c.gamma * dt);
    const double target = im.u_old(i) + dt * im.v_old(i) +
                          dt * dt * ((0.5 - c.beta) * im.a_old(i) + c.beta * a_dirichlet[k]);
    if (long_step)
      lift(i) = target - im.u_old(i);
    else
      d.displacement(i) = target;
  }
  d.displacement.compress(VectorOperation::insert);
  d.hanging_constraints.distribute(d.displacement);
  if (long_step)
  {
    lift.compress(VectorOperation::insert);
    build_lift_constraints(d, im, lift);
    lifting = lift.linfty_norm() > 0.0;
  }
  return a_dirichlet;
}

/// Whether the multigrid hierarchy must be rebuilt before the next solve: none yet, another
/// step length, reuse off, or the last solve needed twice (+10) the iterations of the first
/// solve after the set-up (the matrix has moved away from the one it was built for).
bool preconditioner_outdated(const FarFieldSolver::Data& d, const ImplicitData& im,
                             const double dt)
{
  if (!d.prm.reuse_preconditioner || im.preconditioner_dt == 0.0)
    return true;
  if (std::abs(dt - im.preconditioner_dt) > 1e-9 * dt)
    return true;
  return !im.first_solve_after_setup &&
         im.last_iterations > 2 * im.iterations_after_setup + 10;
}

/// One Newton correction: AMG-preconditioned CG or GMRES, or a sparse LU, on the condensed
/// system, added to the displacement. Returns what failed ("" on success).
std::string apply_newton_correction(FarFieldSolver::Data& d, ImplicitData& im, const double dt,
                                    const double residual, const bool lifting,
                                    ImplicitStepStatistics& stats)
{
  const auto t0 = std::chrono::steady_clock::now();
  const bool direct = d.prm.linear_solver == LinearSolverType::direct;
  if (!direct && preconditioner_outdated(d, im, dt))
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData amg;
    amg.elliptic = true;
    amg.higher_order_elements = d.prm.degree > 1;
    amg.smoother_sweeps = 2;
    amg.aggregation_threshold = 0.02;
    amg.constant_modes = im.constant_modes;
    im.preconditioner.initialize(im.matrix, amg);
    im.preconditioner_dt = dt;
    im.first_solve_after_setup = true;
    ++stats.preconditioner_setups;
  }
  const auto t1 = std::chrono::steady_clock::now();
  SolverControl control(d.prm.max_linear_iterations, d.prm.linear_relative_tolerance * residual);
  im.increment = 0.0;
  try
  {
    if (direct)
    {
      TrilinosWrappers::SolverDirect solver(
        control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
      solver.solve(im.matrix, im.increment, im.rhs);
    }
    else if (d.prm.linear_solver == LinearSolverType::cg)
    {
      TrilinosWrappers::SolverCG solver(control);
      solver.solve(im.matrix, im.increment, im.rhs, im.preconditioner);
    }
    else
    {
      TrilinosWrappers::SolverGMRES solver(control);
      solver.solve(im.matrix, im.increment, im.rhs, im.preconditioner);
    }
  }
  catch (const ExceptionBase& e)
  {
    im.preconditioner_dt = 0.0; // a fresh hierarchy for the retry
    // deal.II's own words without its source location and stack trace.
    std::ostringstream info;
    e.print_info(info);
    std::string words = info.str();
    while (!words.empty() && std::isspace(static_cast<unsigned char>(words.back())))
      words.pop_back();
    const std::size_t first = words.find_first_not_of(" \n");
    return "linear solver: " + (first == std::string::npos ? std::string(e.what())
                                                            : words.substr(first));
  }
  catch (const std::exception& e)
  {
    im.preconditioner_dt = 0.0;
    return std::string("linear solver: ") + e.what();
  }
  const auto t2 = std::chrono::steady_clock::now();
  stats.preconditioner_seconds += std::chrono::duration<double>(t1 - t0).count();
  stats.solve_seconds += std::chrono::duration<double>(t2 - t1).count();
  im.last_iterations = control.last_step();
  if (im.first_solve_after_setup)
  {
    im.iterations_after_setup = im.last_iterations;
    im.first_solve_after_setup = false;
  }
  stats.linear_iterations += control.last_step();
  (lifting ? im.lift_constraints : d.increment_constraints).distribute(im.increment);
  d.displacement += im.increment;
  return {};
}

/// v_{n+1}, the Dirichlet dofs' exact values, the committed states, the energies of the step.
void finish_step(FarFieldSolver::Data& d, ImplicitData& im, const AlphaCoefficients& c,
                 const double dt, const double t_new, const std::vector<double>& a_dirichlet,
                 const EvaluationSums& sums)
{
  // The boundary forces of the converged system, where generalized alpha's equations of motion
  // hold (integrate_boundary_forces).
  if (c.alpha_m != 0.0 || c.alpha_f != 0.0)
    d.boundary_alpha = d.boundary_forces();
  // v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}); Dirichlet dofs get their exact value.
  d.velocity = im.v_old;
  d.velocity.add(dt * (1.0 - c.gamma), im.a_old, dt * c.gamma, d.acceleration);
  for (std::size_t k = 0; k < d.dirichlet_dofs.size(); ++k)
  {
    const DirichletDof& dirichlet = d.dirichlet_dofs[k];
    d.velocity(dirichlet.dof) = d.dirichlet_velocity(dirichlet, t_new);
    d.acceleration(dirichlet.dof) = a_dirichlet[k];
  }
  d.velocity.compress(VectorOperation::insert);
  d.acceleration.compress(VectorOperation::insert);
  d.hanging_constraints.distribute(d.velocity);
  d.hanging_constraints.distribute(d.acceleration);

  d.time = t_new;
  ++d.step;
  d.commit_states();
  d.last_sums = sums;
  d.dissipated_energy += Utilities::MPI::sum(sums.dissipated, d.comm);
  if (c.alpha_f != 0.0)
  {
    // Stress, internal forces and strain energy at u_{n+1} (the Newton system was at
    // u_{n+1-af}); the committed states stay those of the converged system.
    d.ghosted = d.displacement;
    d.last_sums.strain_energy = d.evaluate_internal_forces(d.ghosted, nullptr).strain_energy;
  }
  d.assemble_external_forces(t_new, nullptr);
  const double power = d.external_power();
  d.book_external_work(0.5 * dt * (d.last_power + power));
  d.last_power = power;
}
} // namespace

void FarFieldSolver::advance_implicit(const double dt)
{
  Data& d = *data;
  d.material_time_step = dt;
  if (!d.implicit)
    initialize_implicit(d);
  ImplicitData& im = *d.implicit;
  const AlphaCoefficients c = coefficients(d.prm);
  const double t_new = d.time + dt;
  const double t_alpha = d.time + (1.0 - c.alpha_f) * dt;

  im.u_old = d.displacement;
  im.v_old = d.velocity;
  im.a_old = d.acceleration;

  assemble_condensed_external_forces(d, im, t_alpha);

  const bool long_step = dt > 2.0 * shortest_wave_transit();
  bool lift_pending = false;
  const std::vector<double> a_dirichlet =
      predict_displacement(d, im, c, dt, t_new, long_step, lift_pending);

  const double a_factor = 1.0 / (c.beta * dt * dt);
  const double mass_factor = (1.0 - c.alpha_m) * a_factor;
  const double stiffness_factor = 1.0 - c.alpha_f;
  auto update_acceleration = [&]()
  {
    // a_{n+1} = (u - u_n - dt v_n) / (beta dt^2) - (1/2 - beta)/beta a_n
    d.acceleration = d.displacement;
    d.acceleration.add(-1.0, im.u_old, -dt, im.v_old);
    d.acceleration *= a_factor;
    d.acceleration.add(-(0.5 - c.beta) / c.beta, im.a_old);
  };

  ImplicitStepStatistics& stats = d.implicit_statistics;
  stats = ImplicitStepStatistics();
  double first_residual = 0.0, previous_residual = 0.0, last_correction = 0.0;
  // Corrections below 1e-12 of the smallest cell (root mean square per dof) change strains by
  // less than F = I + grad u resolves near rest: once Newton has cut the residual tenfold,
  // the step is converged to round-off.
  const double correction_floor =
      1e-12 * d.prm.interface_cell_size * std::sqrt(double(d.displacement.size()));
  double step_increment = 0.0;
  bool converged = false;
  EvaluationSums sums;
  std::string failure;
  // Where a failed step stopped: its cells' evaluation or a linear solve, at this iteration.
  enum class Stage { newton, cells, linear_solve } failed_in = Stage::newton;
  unsigned int failed_iteration = 0;
  for (unsigned int it = 0; it <= d.prm.max_newton_iterations; ++it)
  {
    update_acceleration();
    TrilinosWrappers::MPI::Vector work(d.displacement);
    work.sadd(1.0 - c.alpha_f, c.alpha_f, im.u_old);
    im.u_alpha = work;
    work = d.acceleration;
    work.sadd(1.0 - c.alpha_m, c.alpha_m, im.a_old);
    im.a_alpha = work;
    const auto assembly_start = std::chrono::steady_clock::now();
    try
    {
      sums = assemble_newton_system(d, mass_factor, stiffness_factor,
                                    lift_pending ? im.lift_constraints : d.increment_constraints);
    }
    catch (const std::runtime_error& e)
    {
      failure = e.what();
      failed_in = Stage::cells;
      failed_iteration = it;
      break;
    }
    stats.assembly_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - assembly_start).count();
    im.rhs += im.external_condensed;
    const double residual = im.rhs.l2_norm();
    if (it == 0)
      first_residual = residual;
    stats.final_residual = residual;
    // Scale: the first residual of the step, or the internal forces when the predictor is
    // already (nearly) exact.
    const double scale = std::max(it == 0 ? 0.0 : first_residual, d.internal_force_raw.l2_norm());
    // Or the residual sits at its round-off floor: the last correction is negligible against
    // the step's increment, or the residual stopped falling four orders below the force scale
    // (Newton converges quadratically until round-off; a far field nearly at rest, as in a
    // hybrid run before the wave arrives, has its floor at 1e-5 of its tiny forces).
    const bool stagnated =
        it >= 2 && residual > 0.5 * previous_residual && residual <= 1e-4 * scale;
    previous_residual = residual;
    // A lifted first system carries the Dirichlet motion still to be made: never converged.
    if (!lift_pending &&
        (residual <= d.prm.newton_absolute_tolerance ||
        residual <= d.prm.newton_relative_tolerance * scale || stagnated ||
        (it > 0 &&
         (last_correction <= std::max(d.prm.newton_relative_tolerance, 1e-10) * step_increment ||
          (last_correction <= correction_floor && residual <= 0.1 * first_residual)))))
    {
      converged = true;
      break;
    }
    if (it == d.prm.max_newton_iterations)
      break;

    failure = apply_newton_correction(d, im, dt, residual, lift_pending, stats);
    lift_pending = false;
    if (!failure.empty())
    {
      failed_in = Stage::linear_solve;
      failed_iteration = it;
      break;
    }
    last_correction = im.increment.l2_norm();
    TrilinosWrappers::MPI::Vector step(d.displacement);
    step -= im.u_old;
    step_increment = step.l2_norm();
    ++stats.newton_iterations;
  }

  if (!converged)
  {
    d.displacement = im.u_old;
    d.velocity = im.v_old;
    d.acceleration = im.a_old;
    std::ostringstream message;
    message << "FE implicit step at t = " << d.time << " s, dt = " << dt << " s: ";
    // The residuals, once the step has one (a failure in the first evaluation of the cells, at
    // the predictor, comes before any).
    std::ostringstream residuals;
    residuals << " (last residual " << stats.final_residual << " N, first " << first_residual
              << " N)";
    switch (failed_in)
    {
    case Stage::cells:
      if (failed_iteration == 0)
        message << "the cells could not be evaluated at the step's predicted state";
      else
        message << "the cells could not be evaluated after Newton correction "
                << failed_iteration << residuals.str();
      break;
    case Stage::linear_solve:
      message << "the linear solve of Newton correction " << failed_iteration + 1
              << " failed" << residuals.str();
      break;
    case Stage::newton:
      message << "Newton did not converge in " << stats.newton_iterations << " iterations"
              << residuals.str();
      break;
    }
    if (!failure.empty())
      message << ": " << failure;
    message << "; reduce the time step";
    throw std::runtime_error(message.str());
  }

  finish_step(d, im, c, dt, t_new, a_dirichlet, sums);
}
} // namespace vulnus::fem
