// A following interface (Hybrid/Interface = following, docs/hybrid_interface.md): each
// interface node of the far field is spread over the MPM grid nodes around where it is now,
// with the trilinear weights of a material point, instead of being the grid node it started
// on. On the grid the interface is a second velocity field, affine about each node with its
// far-field velocity gradient, that sticks to the MPM field as bodies do in MPM's multi-field
// contact (Bardenhagen et al. 2001): at every shared node both take their centre-of-mass
// velocity, and the interface nodes take their field's change back like FLIP. Momentum
// crosses exactly however far the interface has moved.
#include "coupling/hybrid_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::coupling
{
void HybridSolver::place_interface()
{
  const mpm::Grid& grid = mpm_solver->background_grid();
  const double h = grid.cell_size();
  // Every interface node's displacement, from the FE rank owning it.
  const std::vector<fem::NodeRecord>& nodes = fe_solver->interface_nodes();
  std::vector<double> packed(3 * keys.size(), 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    const dealii::Tensor<1, 3> u = fe_solver->displacement(nodes[i]);
    for (unsigned int c = 0; c < 3; ++c)
      packed[3 * fe_node_index[i] + c] = u[c];
  }
  mpm_solver->rank_group().sum(packed.data(), static_cast<int>(packed.size()));

  // Offsets in cells from the home node: a node that has not moved has weight 1 there alone.
  std::vector<std::int64_t> node_key;
  std::vector<double> weight;
  std::vector<std::uint32_t> begin(1, 0);
  std::vector<mpm::Vector3> position(keys.size());
  std::string problem;
  for (std::size_t k = 0; k < keys.size() && problem.empty(); ++k)
  {
    const mpm::Vector3 s = mpm::Vector3(packed[3 * k], packed[3 * k + 1], packed[3 * k + 2]) / h;
    position[k] = grid.node_position(keys[k]) + h * s;
    const std::array<int, 3> home = grid.node_ijk(keys[k]);
    int base[3];
    double frac[3];
    for (int d = 0; d < 3; ++d)
    {
      // Within a billionth of a cell of a grid plane (a wave's first tail moves the node by
      // 1e-100 m) the node is on it: weights that small would underflow against the masses.
      const double nearest = std::round(s[d]);
      const double whole = std::abs(s[d] - nearest) < 1e-9 ? nearest : std::floor(s[d]);
      base[d] = home[d] + static_cast<int>(whole);
      frac[d] = std::abs(s[d] - nearest) < 1e-9 ? 0.0 : s[d] - whole;
    }
    for (int corner = 0; corner < 8; ++corner)
    {
      double w = 1.0;
      int ijk[3];
      for (int d = 0; d < 3; ++d)
      {
        const int up = (corner >> d) & 1;
        ijk[d] = base[d] + up;
        w *= up ? frac[d] : 1.0 - frac[d];
      }
      if (w == 0.0)
        continue;
      if (!grid.has_node(ijk[0], ijk[1], ijk[2]))
      {
        const mpm::Vector3 x = grid.node_position(keys[k]) + h * s;
        std::ostringstream o;
        o << "the far field's interface node that started at (" << grid.node_position(keys[k]).transpose()
          << ") m has moved to (" << x.transpose()
          << ") m, next to the MPM grid's edge; widen Grid/Domain min and Domain max";
        problem = o.str();
        break;
      }
      node_key.push_back(grid.node_key(ijk[0], ijk[1], ijk[2]));
      weight.push_back(w);
    }
    begin.push_back(static_cast<std::uint32_t>(node_key.size()));
  }
  if (!problem.empty())
    throw std::runtime_error(problem);
  interface_position = std::move(position);

  std::vector<std::int64_t> shared = node_key;
  std::sort(shared.begin(), shared.end());
  shared.erase(std::unique(shared.begin(), shared.end()), shared.end());
  spread_begin = std::move(begin);
  spread_weight = std::move(weight);
  spread_node.resize(node_key.size());
  for (std::size_t e = 0; e < node_key.size(); ++e)
    spread_node[e] = static_cast<std::uint32_t>(
      std::lower_bound(shared.begin(), shared.end(), node_key[e]) - shared.begin());
  if (shared != grid_keys || mpm_solver->shared_nodes().partner != this)
  {
    grid_keys = std::move(shared);
    mpm_solver->share_nodes({split.coupled_body, grid_keys, this});
  }
  spread_interface_masses();
  grid_velocity_start.assign(grid_keys.size(), mpm::Vector3::Zero());
  grid_velocity_end.assign(grid_keys.size(), mpm::Vector3::Zero());
}

void HybridSolver::spread_interface_masses()
{
  grid_fe_share.assign(grid_keys.size(), 0.0);
  for (std::size_t k = 0; k < keys.size(); ++k)
    for (std::uint32_t e = spread_begin[k]; e < spread_begin[k + 1]; ++e)
      grid_fe_share[spread_node[e]] += spread_weight[e] * fe_mass[k];
}

void HybridSolver::gather_interface_gradients()
{
  const std::vector<dealii::Tensor<2, 3>> mine = fe_solver->interface_velocity_gradients();
  std::vector<double> packed(9 * keys.size(), 0.0);
  for (std::size_t i = 0; i < mine.size(); ++i)
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        packed[9 * fe_node_index[i] + 3 * a + b] = mine[i][a][b];
  mpm_solver->rank_group().sum(packed.data(), static_cast<int>(packed.size()));
  interface_gradient.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        interface_gradient[k](a, b) = packed[9 * k + 3 * a + b];
}

std::vector<mpm::Vector3>
HybridSolver::spread_interface_momentum(const std::vector<mpm::Vector3>& v) const
{
  const mpm::Grid& grid = mpm_solver->background_grid();
  std::vector<mpm::Vector3> momentum(grid_keys.size(), mpm::Vector3::Zero());
  for (std::size_t k = 0; k < keys.size(); ++k)
    for (std::uint32_t e = spread_begin[k]; e < spread_begin[k + 1]; ++e)
    {
      const std::uint32_t g = spread_node[e];
      const mpm::Vector3 offset = grid.node_position(grid_keys[g]) - interface_position[k];
      momentum[g] += (spread_weight[e] * fe_mass[k]) * (v[k] + interface_gradient[k] * offset);
    }
  return momentum;
}

void HybridSolver::predict_following(const double fe_dt, const double mpm_dt,
                                     const mpm::SharedNodeState& mpm_side)
{
  gather_fe_interface_state();
  gather_interface_gradients();
  const mpm::Grid& grid = mpm_solver->background_grid();
  const std::size_t n = grid_keys.size();
  // Each interface node's velocity after its own force (and the window's correction).
  std::vector<mpm::Vector3> fe_free(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k)
    fe_free[k] = fe_velocity[k] + (fe_dt * fe_force[k] + correction[k]) / fe_mass[k];
  const std::vector<mpm::Vector3> fe_momentum = spread_interface_momentum(fe_free);
  // Both fields stick at every shared node: each takes the node's centre-of-mass velocity,
  // the momentum one gains the other loses.
  std::vector<mpm::Vector3> fe_change(n);
  for (std::size_t g = 0; g < n; ++g)
  {
    const double m_fe = grid_fe_share[g];
    const mpm::Vector3 fe_field = fe_momentum[g] / m_fe;
    const double m_mpm = mpm_side.mass[g];
    mpm::Vector3 start = fe_field, end = fe_field;
    if (m_mpm > 0.0)
    {
      start = mpm_side.momentum[g] / m_mpm;
      end = (mpm_side.momentum[g] + mpm_dt * mpm_side.force[g] + fe_momentum[g]) / (m_mpm + m_fe);
    }
    mpm::apply_face_conditions(grid, split.mpm.domain_faces, grid_keys[g], end);
    grid_velocity_start[g] = start;
    grid_velocity_end[g] = end;
    fe_change[g] = end - fe_field;
  }
  // The interface nodes take their field's change back, like FLIP: their own motion within
  // a cell stays theirs.
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    mpm::Vector3 v = fe_free[k];
    for (std::uint32_t e = spread_begin[k]; e < spread_begin[k + 1]; ++e)
      v += spread_weight[e] * fe_change[spread_node[e]];
    mpm::apply_face_conditions(grid, split.mpm.domain_faces, keys[k], v);
    velocity_start[k] = fe_velocity[k];
    velocity_end[k] = v;
  }
}

void HybridSolver::book_mpm_side_following(const double dt, const mpm::SharedNodeState& mpm_side,
                                           const std::vector<mpm::Vector3>& v_start,
                                           const std::vector<mpm::Vector3>& v_end)
{
  const std::size_t n = grid_keys.size();
  std::vector<mpm::Vector3> reaction(n, mpm::Vector3::Zero());
  for (std::size_t g = 0; g < n; ++g)
  {
    if (mpm_side.mass[g] <= 0.0)
      continue;
    reaction[g] = mpm_side.mass[g] * (v_end[g] - v_start[g]) / dt - mpm_side.force[g];
    book.mpm_work -= dt * reaction[g].dot(v_end[g]);
    book.mpm_impulse += dt * reaction[g];
  }
  // Each grid node's reaction goes to the interface nodes spread on it, by their mass there,
  // to be taken back through them in the next window's prediction.
  for (std::size_t k = 0; k < keys.size(); ++k)
    for (std::uint32_t e = spread_begin[k]; e < spread_begin[k + 1]; ++e)
    {
      const std::uint32_t g = spread_node[e];
      created[k] += (spread_weight[e] * fe_mass[k] / grid_fe_share[g]) * (dt * reaction[g]);
    }
}

void HybridSolver::stick_to_interface(const double dt, const mpm::SharedNodeState& mpm_side)
{
  const mpm::Grid& grid = mpm_solver->background_grid();
  const std::vector<mpm::Vector3> fe_momentum = spread_interface_momentum(velocity_end);
  for (std::size_t g = 0; g < grid_keys.size(); ++g)
  {
    const double m_mpm = mpm_side.mass[g];
    if (!(m_mpm > 0.0))
      continue;
    grid_velocity_start[g] = mpm_side.momentum[g] / m_mpm;
    mpm::Vector3 end = (mpm_side.momentum[g] + dt * mpm_side.force[g] + fe_momentum[g]) /
                       (m_mpm + grid_fe_share[g]);
    mpm::apply_face_conditions(grid, split.mpm.domain_faces, grid_keys[g], end);
    grid_velocity_end[g] = end;
  }
}

void HybridSolver::exchange_following(const double time, const double dt,
                                      const mpm::SharedNodeState& mpm_side,
                                      std::vector<mpm::Vector3>& v_start,
                                      std::vector<mpm::Vector3>& v_end)
{
  const bool same_step = split.hybrid.scheme == CouplingScheme::same_step;
  const double window = same_step ? dt : window_end - window_start;
  if (same_step || time <= window_start + 1e-9 * window)
  {
    start_window_correction();
    predict_following(window, dt, mpm_side);
    advance_fe(window);
  }
  else
    stick_to_interface(dt, mpm_side);
  v_start = grid_velocity_start;
  v_end = grid_velocity_end;
  book_mpm_side_following(dt, mpm_side, v_start, v_end);
}
} // namespace vulnus::coupling
