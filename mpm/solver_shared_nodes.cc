// The solver's side of the node sharing with a partner solver: gathers the MPM mass and force at the shared nodes after the grid update (summed over the ranks, a node on a cut
// plane counted once), and imposes the returned velocities at the nodes this rank holds.
#include "mpm/solver.h"

#include <stdexcept>

namespace vulnus::mpm
{
void Solver::share_nodes(const SharedNodes& nodes)
{
  if (nodes.body >= particles.n_bodies())
    throw std::invalid_argument("share_nodes: no body " + std::to_string(nodes.body));
  if (grid_settings.body_is_rigid[nodes.body])
    throw std::invalid_argument("share_nodes: body '" + parameters.bodies[nodes.body].name +
                                "' is rigid; only a deformable body can share nodes");
  for (const std::int64_t key : nodes.keys)
    if (key < 0 || static_cast<std::size_t>(key) >= grid.n_box_nodes())
      throw std::invalid_argument("share_nodes: node key outside the grid");
  shared = nodes;
  // The interface impulse m (v_end - v_start) the exchange books is what FLIP gives the
  // points; a blend with PIC would give them m v_end - p instead. Coupled runs use FLIP.
  kinematics.flip_fraction = 1.0;
  kinematics.affine = transfer.affine = false;
  parameters.velocity_transfer = VelocityTransfer::flip; // no XPIC passes for a FLIP update
  const std::size_t n = nodes.keys.size();
  shared_state.mass.assign(n, 0.0);
  shared_state.force.assign(n, Vector3::Zero());
  shared_state.momentum.assign(n, Vector3::Zero());
  shared_velocity_start.assign(n, Vector3::Zero());
  shared_velocity_end.assign(n, Vector3::Zero());
}

void Solver::exchange_shared_nodes(const double dt)
{
  const std::size_t n_bodies = fields.n_bodies;
  const std::size_t b = shared.body;
  for (std::size_t k = 0; k < shared.keys.size(); ++k)
  {
    const std::int32_t slot = grid.slot(shared.keys[k]);
    if (slot < 0 || fields.data[slot * n_bodies + b].mass <= 0.0)
    {
      shared_state.mass[k] = 0.0;
      shared_state.force[k].setZero();
      shared_state.momentum[k].setZero();
      continue;
    }
    const NodeBodyData& d = fields.data[slot * n_bodies + b];
    shared_state.mass[k] = d.mass;
    shared_state.force[k] = d.force + d.mass * parameters.gravity;
    shared_state.momentum[k] = d.mass * fields.velocity[slot * n_bodies + b];
  }
  sum_shared_state_over_ranks();
  shared.partner->exchange(current_time, dt, shared_state, shared_velocity_start,
                          shared_velocity_end);
  for (std::size_t k = 0; k < shared.keys.size(); ++k)
  {
    const std::int32_t slot = grid.slot(shared.keys[k]);
    if (slot < 0 || fields.data[slot * n_bodies + b].mass <= 0.0)
      continue;
    fields.velocity[slot * n_bodies + b] = shared_velocity_start[k];
    // Both velocities obey the supports already: the interface ledger books that node's work.
    if (!fields.support_change.empty())
      fields.support_change[slot * n_bodies + b].setZero();
  }
  impose_shared_velocities(fields.velocity_new, false);
}

void Solver::sum_shared_state_over_ranks()
{
  if (!ranks.distributed())
    return;
  // After the node exchange both ranks of a cut-plane node hold its complete data; only the
  // lower one contributes.
  const std::size_t n = shared.keys.size();
  std::vector<double> packed(7 * n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
  {
    if (shared_state.mass[k] <= 0.0 || !grid_settings.owns_node(shared.keys[k]))
      continue;
    packed[7 * k] = shared_state.mass[k];
    for (int c = 0; c < 3; ++c)
    {
      packed[7 * k + 1 + c] = shared_state.force[k][c];
      packed[7 * k + 4 + c] = shared_state.momentum[k][c];
    }
  }
  ranks.sum(packed.data(), static_cast<int>(packed.size()));
  for (std::size_t k = 0; k < n; ++k)
  {
    const double* q = &packed[7 * k];
    shared_state.mass[k] = q[0];
    shared_state.force[k] = Vector3(q[1], q[2], q[3]);
    shared_state.momentum[k] = Vector3(q[4], q[5], q[6]);
  }
}

void Solver::impose_shared_velocities(std::vector<Vector3>& velocity, const bool projected_again)
{
  const std::size_t n_bodies = fields.n_bodies;
  const std::size_t b = shared.body;
  const std::vector<double>* partner_mass = projected_again ? shared.partner->blend_masses() : nullptr;
  for (std::size_t k = 0; k < shared.keys.size(); ++k)
  {
    const std::int32_t slot = grid.slot(shared.keys[k]);
    if (slot < 0 || fields.data[slot * n_bodies + b].mass <= 0.0)
      continue;
    Vector3& v = velocity[slot * n_bodies + b];
    if (partner_mass)
    {
      // A node at the edge of the points holds little of their mass: the partner's velocity
      // dominates there, and the points' own (projected again) inside the zone.
      const double m = fields.data[slot * n_bodies + b].mass;
      const double m_partner = (*partner_mass)[k];
      v = (m * v + m_partner * shared_velocity_end[k]) / (m + m_partner);
    }
    else
      v = shared_velocity_end[k];
    apply_face_conditions(grid, grid_settings.faces, shared.keys[k], v);
  }
}
} // namespace vulnus::mpm
