// Forces across the constrained boundary of the far field (interface nodes and face supports)
// and their time integrals with the integrator's own weights, so that the impulses booked here
// are exactly the momentum the body's free nodes received (docs/DESIGN.md section 6).
#include "fem/far_field_data.h"

namespace vulnus::fem
{
using namespace dealii;

BoundaryForces FarFieldSolver::Data::boundary_forces() const
{
  // X_i = f_ext - f_int - ((M a)_i - m_i a_i): what the rest of the body transmits to dof i.
  auto transmitted = [this](const types::global_dof_index i) {
    return external_force_raw(i) - internal_force_raw(i) - inertia_coupling_raw(i);
  };
  BoundaryForces forces;
  forces.interface.resize(interface_nodes.size());
  for (std::size_t n = 0; n < interface_nodes.size(); ++n)
    for (unsigned int c = 0; c < 3; ++c)
      forces.interface[n][c] = transmitted(interface_nodes[n].dofs[c]);
  for (const DirichletDof& dirichlet : dirichlet_dofs)
    if (dirichlet.source != DirichletSource::interface)
      forces.supports[dirichlet.face][dirichlet.component] -= transmitted(dirichlet.dof);
  return forces;
}

void FarFieldSolver::Data::integrate_boundary_forces(const double dt)
{
  BoundaryForces end = boundary_forces();
  // Staggered central difference: v_{n+1/2} - v_{n-1/2} = dt M^{-1} f(u_n), the start state.
  // Velocity Verlet, Newmark and generalized-alpha: v_{n+1} - v_n = dt ((1 - gamma) a_n +
  // gamma a_{n+1}), exact for the first two (the equations of motion hold at both ends).
  // Generalized alpha's hold at its intermediate point: M ((1 - am) a_{n+1} + am a_n) =
  // F_alpha, so the forces matching a_{n+1} are Y_{n+1} = (X_alpha - am Y_n) / (1 - am) with
  // X_alpha the boundary forces of the converged system; boundary_now carries Y.
  const double alpha_m = is_implicit() ? implicit_alpha_m(prm) : 0.0;
  if (is_implicit() && (alpha_m != 0.0 || implicit_alpha_f(prm) != 0.0))
  {
    const BoundaryForces& x = boundary_alpha;
    for (std::size_t n = 0; n < end.interface.size(); ++n)
      end.interface[n] = (x.interface[n] - alpha_m * boundary_now.interface[n]) / (1.0 - alpha_m);
    for (unsigned int b = 0; b <= n_slab_faces; ++b)
      end.supports[b] = (x.supports[b] - alpha_m * boundary_now.supports[b]) / (1.0 - alpha_m);
  }
  const double w_end = prm.staggered_velocity ? 0.0 : integrator_gamma(prm);
  const double w_start = 1.0 - w_end;
  interface_impulse_last_step.resize(end.interface.size());
  for (std::size_t n = 0; n < end.interface.size(); ++n)
    interface_impulse_last_step[n] = dt * (w_start * boundary_now.interface[n] + w_end * end.interface[n]);
  for (unsigned int b = 0; b <= n_slab_faces; ++b)
    support_impulse[b] += dt * (w_start * boundary_now.supports[b] + w_end * end.supports[b]);
  // R = m a - X: the inertia part as the supported dofs' momentum change over the step.
  if (dirichlet_velocity_booked.size() != dirichlet_dofs.size())
    reset_booked_dirichlet_velocities();
  for (std::size_t k = 0; k < dirichlet_dofs.size(); ++k)
  {
    const DirichletDof& dirichlet = dirichlet_dofs[k];
    if (dirichlet.source == DirichletSource::interface)
      continue;
    const double v = velocity(dirichlet.dof);
    support_impulse[dirichlet.face][dirichlet.component] +=
      lumped_mass(dirichlet.dof) * (v - dirichlet_velocity_booked[k]);
    dirichlet_velocity_booked[k] = v;
  }
  boundary_now = end;
}

void FarFieldSolver::Data::reset_booked_dirichlet_velocities()
{
  dirichlet_velocity_booked.resize(dirichlet_dofs.size());
  for (std::size_t k = 0; k < dirichlet_dofs.size(); ++k)
    dirichlet_velocity_booked[k] = velocity(dirichlet_dofs[k].dof);
}
} // namespace vulnus::fem
