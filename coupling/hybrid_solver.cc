// Hybrid MPM-FE stepping: interface matching, the summed-node prediction, the FE step and the
// interface ledger. Distributed: every rank holds all interface nodes in one order (by grid
// key); the MPM state arrives summed over the MPM ranks, the FE state is summed from the FE
// ranks owning the nodes, so every rank predicts the same velocities and keeps the same ledger.
#include "coupling/hybrid_solver.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::coupling
{
namespace
{
mpm::Vector3 to_eigen(const dealii::Tensor<1, 3>& t) { return mpm::Vector3(t[0], t[1], t[2]); }

dealii::Tensor<1, 3> to_tensor(const mpm::Vector3& v)
{
  dealii::Tensor<1, 3> t;
  for (unsigned int c = 0; c < 3; ++c)
    t[c] = v[c];
  return t;
}
} // namespace

HybridSolver::HybridSolver(const HybridScene& scene, MPI_Comm communicator,
                           const std::function<void(fem::FarFieldSolver&)>& before_fe_setup)
  : split(scene), comm(communicator), prepare_far_field(before_fe_setup),
    start_zone_min(scene.hybrid.zone_min), start_zone_max(scene.hybrid.zone_max)
{
  mpm_solver = std::make_unique<mpm::Solver>(split.mpm, communicator);
  fe_solver = build_far_field();
  match_interface_nodes(communicator);
  for (std::vector<mpm::Vector3>* v :
       {&velocity_start, &velocity_end, &created, &correction})
    v->assign(keys.size(), mpm::Vector3::Zero());
  if (follows_interface())
    place_interface();
  else
    mpm_solver->share_nodes({split.coupled_body, keys, this});
}

void HybridSolver::match_interface_nodes(MPI_Comm communicator)
{
  const mpm::Grid& grid = mpm_solver->background_grid();
  const double h = grid.cell_size();
  std::vector<std::int64_t> my_keys;
  keys.clear();
  std::string problem;
  for (const fem::NodeRecord& node : fe_solver->interface_nodes())
  {
    int ijk[3];
    for (int d = 0; d < 3; ++d)
      ijk[d] = static_cast<int>(std::lround((node.position[d] - grid.origin()[d]) / h));
    const mpm::Vector3 x(node.position[0], node.position[1], node.position[2]);
    if (!grid.has_node(ijk[0], ijk[1], ijk[2]) ||
        (grid.node_position(grid.node_key(ijk[0], ijk[1], ijk[2])) - x).norm() > 1e-6 * h)
    {
      std::ostringstream s;
      s << "the MPM zone's bounds: the FE interface node at (" << x[0] << ", " << x[1]
        << ", " << x[2] << ") m is not an MPM grid node; the zone must lie on grid nodes";
      problem = s.str();
      break;
    }
    my_keys.push_back(grid.node_key(ijk[0], ijk[1], ijk[2]));
  }
  const mpm::RankGroup& ranks = mpm_solver->rank_group();
  if (const std::string first = ranks.first_message(problem); !first.empty())
    throw std::invalid_argument(first);

  // Every rank lists all interface nodes in one order (by grid key); each FE rank owns some.
  for (const std::vector<std::int64_t>& owned :
       dealii::Utilities::MPI::all_gather(communicator, my_keys))
    keys.insert(keys.end(), owned.begin(), owned.end());
  std::sort(keys.begin(), keys.end());
  if (std::adjacent_find(keys.begin(), keys.end()) != keys.end())
    throw std::logic_error("hybrid: two FE interface nodes sit on one MPM grid node");
  fe_node_index.clear();
  for (const std::int64_t key : my_keys)
    fe_node_index.push_back(
      static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin()));

  const mpm::SlabPartition& slabs = mpm_solver->slabs();
  std::uint64_t elsewhere = 0;
  for (const std::int64_t key : my_keys)
    elsewhere += slabs.rank_of_node(grid, key) != ranks.rank();
  fe_nodes_on_other_mpm_ranks = ranks.sum(elsewhere);

  free_components.assign(keys.size(), mpm::Vector3::Ones());
  for (std::size_t k = 0; k < keys.size(); ++k)
    mpm::apply_face_conditions(grid, split.mpm.domain_faces, keys[k], free_components[k]);

  fe_mass.assign(keys.size(), 0.0);
  const std::vector<double> my_masses = fe_solver->interface_lumped_masses();
  for (std::size_t i = 0; i < fe_node_index.size(); ++i)
    fe_mass[fe_node_index[i]] = my_masses[i];
  ranks.sum(fe_mass.data(), static_cast<int>(fe_mass.size()));
}

HybridSolver::~HybridSolver() = default;

std::unique_ptr<fem::FarFieldSolver> HybridSolver::build_far_field() const
{
  auto far_field = std::make_unique<fem::FarFieldSolver>(split.fe, comm);
  if (prepare_far_field)
    prepare_far_field(*far_field);
  far_field->setup();
  const std::array<double, 3> v0 = split.initial_velocity;
  far_field->set_initial_velocity([v0](const dealii::Point<3>&) {
    dealii::Tensor<1, 3> v;
    for (unsigned int c = 0; c < 3; ++c)
      v[c] = v0[c];
    return v;
  });
  return far_field;
}

void HybridSolver::set_initial_velocity(const std::function<mpm::Vector3(const mpm::Vector3&)>& field)
{
  mpm_solver->set_point_velocities(field, static_cast<int>(split.coupled_body));
  fe_solver->set_initial_velocity([&](const dealii::Point<3>& x) {
    return to_tensor(field(mpm::Vector3(x[0], x[1], x[2])));
  });
}

bool HybridSolver::finished() const { return mpm_solver->finished(); }

void HybridSolver::advance()
{
  const AdaptiveZoneParameters& adaptive = split.hybrid.adaptive;
  if (adaptive.enabled && !window_open &&
      book.mpm_steps >= last_zone_check + adaptive.check_interval)
  {
    last_zone_check = book.mpm_steps;
    const ZoneNeed need = zone_needed();
    if (need.min != split.hybrid.zone_min || need.max != split.hybrid.zone_max)
      grow_zone(need.min, need.max, need.flagged);
  }
  if (adaptive.enabled && !window_open && !retired)
    retire_far_field_without_stiffness();
  if (retired)
  {
    mpm_solver->advance();
    ++book.mpm_steps;
    return;
  }
  const double t = mpm_solver->time();
  const double end = split.mpm.end_time;
  if (split.hybrid.scheme == CouplingScheme::same_step)
  {
    if (follows_interface())
      place_interface();
    mpm_solver->advance(fe_solver->next_time_step());
    ++book.mpm_steps;
    return;
  }
  if (!window_open)
  {
    double window = fe_solver->next_time_step();
    if (split.hybrid.substeps > 0)
      window = std::min(window, split.hybrid.substeps * mpm_solver->stable_time_step());
    // Dashpot windows keep to the length they were halved to (dashpot_windows.cc).
    if (dashpot_windows() && book.dashpot_window_limit > 0.0)
      window = std::min(window, book.dashpot_window_limit);
    // Balanced implicit windows stay within one wave transit of the far field's smallest
    // cell: beyond it the interface gains energy (docs/far_field.md, section 1).
    if (balances_windows() && !dashpot_windows())
      if (const double limit = fe_solver->shortest_wave_transit(); window > limit)
      {
        window = limit;
        ++book.windows_shortened;
        if (book.shortest_window_limit == 0.0 || limit < book.shortest_window_limit)
          book.shortest_window_limit = limit;
      }
    // The adaptive zone looks at the far field at window ends: no window may outlast a check.
    if (adaptive.enabled)
      window = std::min(window, adaptive.check_interval * mpm_solver->stable_time_step());
    window_start = t;
    window_end = std::min(t + window, end);
    window_open = true;
    if (follows_interface())
      place_interface();
  }
  mpm_solver->advance(window_end - t);
  ++book.mpm_steps;
  if (mpm_solver->time() >= window_end - 1e-9 * (window_end - window_start))
    window_open = false;
}

void HybridSolver::gather_fe_interface_state()
{
  // Velocity and force of every interface node from the FE rank owning it.
  const std::vector<dealii::Tensor<1, 3>> forces = fe_solver->interface_nodal_forces();
  const std::vector<fem::NodeRecord>& nodes = fe_solver->interface_nodes();
  std::vector<double> packed(6 * keys.size(), 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    const dealii::Tensor<1, 3> v = fe_solver->velocity(nodes[i]);
    const std::size_t k = fe_node_index[i];
    for (unsigned int c = 0; c < 3; ++c)
    {
      packed[6 * k + c] = v[c];
      packed[6 * k + 3 + c] = forces[i][c];
    }
  }
  mpm_solver->rank_group().sum(packed.data(), static_cast<int>(packed.size()));
  fe_velocity.resize(keys.size());
  fe_force.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    fe_velocity[k] = mpm::Vector3(packed[6 * k], packed[6 * k + 1], packed[6 * k + 2]);
    fe_force[k] = mpm::Vector3(packed[6 * k + 3], packed[6 * k + 4], packed[6 * k + 5]);
  }
}

void HybridSolver::predict_interface(const double dt, const mpm::SharedNodeState& mpm_side)
{
  gather_fe_interface_state();
  const mpm::Grid& grid = mpm_solver->background_grid();
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    // The shared node keeps the FE interface velocity as its own and is accelerated by the
    // summed forces of both sides.
    const mpm::Vector3& v_node = fe_velocity[k];
    const mpm::Vector3& f_fe = fe_force[k];
    const double m_fe = fe_mass[k];
    mpm::Vector3 v = v_node + (dt * (mpm_side.force[k] + f_fe) + correction[k]) /
                                (mpm_side.mass[k] + m_fe);
    // Supports of the grid faces hold the shared node on both sides.
    mpm::apply_face_conditions(grid, split.mpm.domain_faces, keys[k], v);
    velocity_start[k] = v_node;
    velocity_end[k] = v;
  }
}

std::vector<mpm::Vector3> HybridSolver::step_fe(const double dt)
{
  targets.resize(fe_node_index.size());
  for (std::size_t i = 0; i < fe_node_index.size(); ++i)
    targets[i] = to_tensor(velocity_end[fe_node_index[i]]);
  fe_solver->set_interface_velocities(targets);
  fe_solver->advance(dt);

  // The FE body received its interface nodes' momentum change minus the impulse it
  // transmitted to them (its integrator's time integral).
  std::vector<double> packed(3 * keys.size(), 0.0);
  const std::vector<dealii::Tensor<1, 3>>& transmitted = fe_solver->interface_impulses_of_last_step();
  for (std::size_t i = 0; i < transmitted.size(); ++i)
    for (unsigned int c = 0; c < 3; ++c)
      packed[3 * fe_node_index[i] + c] = transmitted[i][c];
  mpm_solver->rank_group().sum(packed.data(), static_cast<int>(packed.size()));
  std::vector<mpm::Vector3> impulse(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k)
    impulse[k] = fe_mass[k] * (velocity_end[k] - velocity_start[k]) -
                 mpm::Vector3(packed[3 * k], packed[3 * k + 1], packed[3 * k + 2]);
  return impulse;
}

void HybridSolver::book_fe_side(const std::vector<mpm::Vector3>& impulse)
{
  ++book.fe_steps;
  const bool staggered = split.fe.staggered_velocity;
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    const mpm::Vector3 v_step =
        staggered ? velocity_end[k] : mpm::Vector3(0.5 * (velocity_end[k] + velocity_start[k]));
    book.fe_work += impulse[k].dot(v_step);
    book.fe_impulse += impulse[k];
    created[k] += impulse[k];
  }
}

void HybridSolver::advance_fe(const double dt) { book_fe_side(step_fe(dt)); }

void HybridSolver::start_window_correction()
{
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    // What the last window created beyond the correction it applied is taken back now.
    correction[k] = -(created[k] - correction[k]);
    created[k].setZero();
  }
}

void HybridSolver::book_mpm_side(const double dt, const mpm::SharedNodeState& mpm_side,
                                 const std::vector<mpm::Vector3>& v_start,
                                 const std::vector<mpm::Vector3>& v_end)
{
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    if (mpm_side.mass[k] <= 0.0)
      continue;
    const mpm::Vector3 reaction =
        mpm_side.mass[k] * (v_end[k] - v_start[k]) / dt - mpm_side.force[k];
    book.mpm_work -= dt * reaction.dot(v_end[k]);
    book.mpm_impulse += dt * reaction;
    created[k] += dt * reaction;
  }
}

void HybridSolver::exchange(const double time, const double dt,
                            const mpm::SharedNodeState& mpm_side,
                            std::vector<mpm::Vector3>& v_start, std::vector<mpm::Vector3>& v_end)
{
  if (follows_interface())
  {
    exchange_following(time, dt, mpm_side, v_start, v_end);
    return;
  }
  if (split.hybrid.scheme == CouplingScheme::same_step)
  {
    start_window_correction();
    predict_interface(dt, mpm_side);
    advance_fe(dt);
    v_start = velocity_start;
    v_end = velocity_end;
    book_mpm_side(dt, mpm_side, v_start, v_end);
    return;
  }
  const double window = window_end - window_start;
  const bool first_substep = time <= window_start + 1e-9 * window;
  const bool last_substep = time + dt >= window_end - 1e-9 * window;
  if (dashpot_windows())
  {
    exchange_dashpot(time, dt, first_substep, mpm_side, v_start, v_end);
    return;
  }
  if (balances_windows())
  {
    exchange_balanced(time, dt, first_substep, last_substep, mpm_side, v_start, v_end);
    return;
  }
  if (first_substep)
  {
    start_window_correction();
    predict_interface(window, mpm_side);
    advance_fe(window);
  }
  substep_velocities(time, dt, first_substep, velocity_start, velocity_end, v_start, v_end);
  book_mpm_side(dt, mpm_side, v_start, v_end);
}

void HybridSolver::substep_velocities(const double time, const double dt, const bool first_substep,
                                      const std::vector<mpm::Vector3>& window_start_velocity,
                                      const std::vector<mpm::Vector3>& window_end_velocity,
                                      std::vector<mpm::Vector3>& v_start,
                                      std::vector<mpm::Vector3>& v_end) const
{
  if (split.fe.staggered_velocity)
  {
    // Central difference: the interface moves with one velocity over the whole window.
    v_start = first_substep ? window_start_velocity : window_end_velocity;
    v_end = window_end_velocity;
    return;
  }
  // End-of-step velocities, interpolated linearly over the window.
  const double window = window_end - window_start;
  const double s0 = (time - window_start) / window;
  const double s1 = std::min(1.0, (time + dt - window_start) / window);
  for (std::size_t k = 0; k < window_start_velocity.size(); ++k)
  {
    const mpm::Vector3 jump = window_end_velocity[k] - window_start_velocity[k];
    v_start[k] = window_start_velocity[k] + s0 * jump;
    v_end[k] = window_start_velocity[k] + s1 * jump;
  }
}

Eigen::Vector3d HybridSolver::impulse_in_transit() const
{
  // Before the next window starts: what the last one created, to be taken back.
  Eigen::Vector3d sum = impulse_left_by_retirement;
  for (std::size_t k = 0; k < keys.size(); ++k)
    sum -= created[k] - correction[k];
  return sum;
}

Eigen::Vector3d HybridSolver::total_momentum() const
{
  const fem::FeDiagnostics d = fe_solver->diagnostics();
  Eigen::Vector3d sum = mpm_solver->diagnostics().momentum + to_eigen(d.momentum) + impulse_in_transit();
  // Inside a balanced window (a run stopped before its last substep) the far field already
  // stands at the window's end: its step's interface impulse, booked at the last substep, is
  // in its momentum but not yet in created.
  if (!fe_state_at_window_start.empty())
    for (const mpm::Vector3& impulse : fe_window_impulse)
      sum -= impulse;
  return sum;
}

double HybridSolver::fe_mechanical_energy() const
{
  const fem::FeDiagnostics d = fe_solver->diagnostics();
  return d.kinetic_energy + d.strain_energy;
}
} // namespace vulnus::coupling
