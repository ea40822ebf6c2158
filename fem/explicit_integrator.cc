// Explicit central-difference step (velocity-Verlet form) with the lumped mass:
//   v_{n+1/2} = v_n + dt/2 a_n, u_{n+1} = u_n + dt v_{n+1/2},
//   a_{n+1} = M^{-1} (f_ext(t_{n+1}) - f_int(u_{n+1})), v_{n+1} = v_{n+1/2} + dt/2 a_{n+1};
// Dirichlet dofs follow their prescribed velocity with u_{n+1} = u_n + dt (v_n + v_{n+1})/2.
// Staggered form (coupling): v_{n+1/2} = v_{n-1/2} + dt a_n, u_{n+1} = u_n + dt v_{n+1/2},
// Dirichlet dofs moving with their prescribed velocity over the step.
#include "fem/far_field_data.h"

#include <deal.II/base/mpi.h>

#include <chrono>

namespace vulnus::fem
{
using namespace dealii;

void FarFieldSolver::evaluate_explicit_forces(const double t)
{
  Data& d = *data;
  d.ghosted = d.displacement;
  // Not at set-up (no step yet): the initial velocities are set after it.
  const bool viscous = d.prm.shock_viscosity.active() && d.material_time_step > 0.0;
  if (viscous)
    d.ghosted_velocity = d.velocity; // v_{n+1/2} after the first half kick
  d.residual = 0.0;
  const auto start = std::chrono::steady_clock::now();
  const EvaluationSums sums =
    d.evaluate_internal_forces(d.ghosted, &d.residual, viscous ? &d.ghosted_velocity : nullptr);
  d.phase_times.internal_forces +=
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  d.assemble_external_forces(t, &d.residual);
  d.commit_states();
  d.last_sums = sums;
  d.dissipated_energy += Utilities::MPI::sum(sums.dissipated, d.comm);
  d.acceleration = d.residual;
  d.acceleration.scale(d.inverse_mass);
}

void FarFieldSolver::advance_explicit(const double dt)
{
  Data& d = *data;
  if (d.prm.staggered_velocity)
  {
    advance_explicit_staggered(dt);
    return;
  }
  d.material_time_step = dt;
  const double t_new = d.time + dt;
  const std::size_t n_dirichlet = d.dirichlet_dofs.size();
  std::vector<double> u_old(n_dirichlet), v_old(n_dirichlet), v_new(n_dirichlet);
  for (std::size_t k = 0; k < n_dirichlet; ++k)
  {
    const auto i = d.dirichlet_dofs[k].dof;
    u_old[k] = d.displacement(i);
    v_old[k] = d.velocity(i);
    v_new[k] = d.dirichlet_velocity(d.dirichlet_dofs[k], t_new);
  }

  d.velocity.add(0.5 * dt, d.acceleration);
  d.displacement.add(dt, d.velocity);
  for (std::size_t k = 0; k < n_dirichlet; ++k)
    d.displacement(d.dirichlet_dofs[k].dof) = u_old[k] + 0.5 * dt * (v_old[k] + v_new[k]);
  d.displacement.compress(VectorOperation::insert);
  d.hanging_constraints.distribute(d.displacement);

  d.time = t_new;
  evaluate_explicit_forces(t_new);

  d.velocity.add(0.5 * dt, d.acceleration);
  for (std::size_t k = 0; k < n_dirichlet; ++k)
  {
    const auto i = d.dirichlet_dofs[k].dof;
    d.velocity(i) = v_new[k];
    d.acceleration(i) = (v_new[k] - v_old[k]) / dt;
  }
  d.velocity.compress(VectorOperation::insert);
  d.acceleration.compress(VectorOperation::insert);
  d.hanging_constraints.distribute(d.velocity);
  d.hanging_constraints.distribute(d.acceleration);
  ++d.step;

  const double power = d.external_power();
  d.book_external_work(0.5 * dt * (d.last_power + power));
  d.last_power = power;
}

void FarFieldSolver::advance_explicit_staggered(const double dt)
{
  Data& d = *data;
  d.material_time_step = dt;
  const double t_mid = d.time + 0.5 * dt;
  const std::size_t n_dirichlet = d.dirichlet_dofs.size();
  std::vector<double> v_old(n_dirichlet), v_step(n_dirichlet);
  for (std::size_t k = 0; k < n_dirichlet; ++k)
  {
    v_old[k] = d.velocity(d.dirichlet_dofs[k].dof);
    v_step[k] = d.dirichlet_velocity(d.dirichlet_dofs[k], t_mid);
  }
  d.velocity.add(dt, d.acceleration);
  for (std::size_t k = 0; k < n_dirichlet; ++k)
  {
    const auto i = d.dirichlet_dofs[k].dof;
    d.velocity(i) = v_step[k];
    d.acceleration(i) = (v_step[k] - v_old[k]) / dt;
  }
  d.velocity.compress(VectorOperation::insert);
  d.acceleration.compress(VectorOperation::insert);
  d.hanging_constraints.distribute(d.velocity);
  d.displacement.add(dt, d.velocity);
  d.hanging_constraints.distribute(d.displacement);

  // Power of the supports and loads over the step, at the velocity of the step (forces at t_n).
  const double power = d.external_power();
  d.book_external_work(dt * power);
  d.last_power = power;

  d.time += dt;
  evaluate_explicit_forces(d.time);
  ++d.step;
}
} // namespace vulnus::fem
