// The far field's side of an adaptive MPM zone: which cells near failure (kept by every force
// evaluation), the material points of cells about to convert, and the hand-over of the state to a mesh
// with a larger hole whose other cells are the same (fine region of the mesh, FeSceneParameters
// focus), matched by position.
#include "fem/far_field_data.h"
#include "fem/tensor_conversion.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>

namespace vulnus::fem
{
using namespace dealii;

namespace
{
using PositionKey = std::array<long long, 3>;

/// Positions of the same mesh line agree to round-off; a millionth of a cell tells them apart.
PositionKey key_of(const Point<3>& x, const double quantum)
{
  return {std::llround(x[0] / quantum), std::llround(x[1] / quantum), std::llround(x[2] / quantum)};
}

/// Displacement gradient and fields at the quadrature points of one cell.
struct CellKinematics
{
  std::vector<Tensor<2, 3>> F;
  std::vector<Tensor<1, 3>> u, v;
};

void evaluate_cell(const FEValues<3>& fe_values, const std::vector<types::global_dof_index>& dofs,
                   const FarFieldSolver::Data::Vector& u, const FarFieldSolver::Data::Vector& v,
                   const FESystem<3>& fe, CellKinematics& out)
{
  const unsigned int n_q = fe_values.n_quadrature_points;
  out.F.assign(n_q, unit_symmetric_tensor<3>());
  out.u.assign(n_q, Tensor<1, 3>());
  out.v.assign(n_q, Tensor<1, 3>());
  for (unsigned int i = 0; i < dofs.size(); ++i)
  {
    const unsigned int c = fe.system_to_component_index(i).first;
    for (unsigned int q = 0; q < n_q; ++q)
    {
      out.F[q][c] += u(dofs[i]) * fe_values.shape_grad_component(i, q, c);
      out.u[q][c] += u(dofs[i]) * fe_values.shape_value_component(i, q, c);
      out.v[q][c] += v(dofs[i]) * fe_values.shape_value_component(i, q, c);
    }
  }
}
} // namespace

std::vector<Point<3>> FarFieldSolver::cells_nearing_failure(const double threshold) const
{
  const Data& d = *data;
  AssertThrow(d.prm.track_failure_proximity,
              ExcMessage("cells_nearing_failure needs FeSceneParameters::track_failure_proximity"));
  std::vector<double> mine;
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (cell->is_locally_owned() && d.cell_failure_proximity[cell->active_cell_index()] >= threshold)
      for (unsigned int c = 0; c < 3; ++c)
        mine.push_back(cell->center()[c]);
  std::vector<Point<3>> centres;
  for (const std::vector<double>& theirs : Utilities::MPI::all_gather(d.comm, mine))
    for (std::size_t i = 0; i + 2 < theirs.size(); i += 3)
      centres.emplace_back(theirs[i], theirs[i + 1], theirs[i + 2]);
  return centres;
}

std::vector<ConvertedPoint>
FarFieldSolver::material_points_inside(const std::array<double, 3>& box_min,
                                       const std::array<double, 3>& box_max,
                                       const unsigned int points_per_axis) const
{
  const Data& d = *data;
  AssertThrow(d.prm.degree == 1 && d.n_q_points == 8,
              ExcMessage("material points from a far field need linear elements"));
  // Midpoints of n x n x n sub-cells: the MPM lattice, and exact for the trilinear fields'
  // mass and momentum.
  const QIterated<3> lattice(QMidpoint<1>(), points_per_axis);
  Data::Vector u(d.owned_dofs, d.relevant_dofs, d.comm);
  Data::Vector v(d.owned_dofs, d.relevant_dofs, d.comm);
  u = d.displacement;
  v = d.velocity;
  FEValues<3> fe_values(d.mapping, d.fe, lattice,
                        update_values | update_gradients | update_JxW_values |
                          update_quadrature_points);
  std::vector<types::global_dof_index> dofs(d.fe.n_dofs_per_cell());
  CellKinematics k;
  std::vector<ConvertedPoint> points;
  for (const auto& cell : d.dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    const Point<3> c = cell->center();
    bool inside = true;
    for (unsigned int a = 0; a < 3 && inside; ++a)
      inside = c[a] > box_min[a] && c[a] < box_max[a];
    if (!inside)
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(dofs);
    evaluate_cell(fe_values, dofs, u, v, d.fe, k);
    const std::size_t first = std::size_t(cell->active_cell_index()) * d.n_q_points;
    for (unsigned int q = 0; q < lattice.size(); ++q)
    {
      // The history of the Gauss point in the same octant (2 x 2 x 2 Gauss, x fastest).
      const Point<3>& xi = lattice.point(q);
      const unsigned int gauss = (xi[0] > 0.5) + 2 * (xi[1] > 0.5) + 4 * (xi[2] > 0.5);
      ConvertedPoint p;
      p.reference_position = fe_values.quadrature_point(q);
      p.displacement = k.u[q];
      p.velocity = k.v[q];
      p.deformation_gradient = k.F[q];
      p.state = d.committed_states[first + gauss];
      p.reference_volume = fe_values.JxW(q);
      p.mass = d.prm.density * p.reference_volume;
      points.push_back(p);
    }
  }
  return points;
}

void FarFieldSolver::take_state_from(const FarFieldSolver& before)
{
  Data& d = *data;
  const Data& old = *before.data;
  const double quantum = 1e-6 * d.prm.interface_cell_size;

  // Every node's displacement, velocity and acceleration, on every rank, by position.
  std::vector<double> packed;
  for (const NodeRecord& node : old.owned_nodes)
  {
    for (unsigned int c = 0; c < 3; ++c)
      packed.push_back(node.position[c]);
    for (const Data::Vector* field : {&old.displacement, &old.velocity, &old.acceleration})
      for (unsigned int c = 0; c < 3; ++c)
        packed.push_back((*field)(node.dofs[c]));
  }
  std::map<PositionKey, std::array<double, 9>> nodal;
  for (const std::vector<double>& theirs : Utilities::MPI::all_gather(d.comm, packed))
    for (std::size_t i = 0; i + 11 < theirs.size(); i += 12)
    {
      std::array<double, 9> fields;
      std::copy(theirs.begin() + i + 3, theirs.begin() + i + 12, fields.begin());
      nodal[key_of(Point<3>(theirs[i], theirs[i + 1], theirs[i + 2]), quantum)] = fields;
    }
  std::string missing;
  for (const NodeRecord& node : d.owned_nodes)
  {
    const auto found = nodal.find(key_of(node.position, quantum));
    if (found == nodal.end())
    {
      missing = "a node of the new far-field mesh has no counterpart in the old one";
      break;
    }
    for (unsigned int c = 0; c < 3; ++c)
    {
      d.displacement(node.dofs[c]) = found->second[c];
      d.velocity(node.dofs[c]) = found->second[3 + c];
      d.acceleration(node.dofs[c]) = found->second[6 + c];
    }
  }
  nodal.clear();

  // Every cell's quadrature-point histories, by cell centre.
  std::vector<char> states;
  const std::size_t record = 3 * sizeof(double) + old.n_q_points * sizeof(materials::PointState);
  for (const auto& cell : old.triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      const std::size_t at = states.size();
      states.resize(at + record);
      const Point<3> c = cell->center();
      std::memcpy(states.data() + at, &c[0], sizeof(double));
      std::memcpy(states.data() + at + sizeof(double), &c[1], sizeof(double));
      std::memcpy(states.data() + at + 2 * sizeof(double), &c[2], sizeof(double));
      std::memcpy(states.data() + at + 3 * sizeof(double),
                  &old.committed_states[std::size_t(cell->active_cell_index()) * old.n_q_points],
                  old.n_q_points * sizeof(materials::PointState));
    }
  std::map<PositionKey, std::vector<materials::PointState>> histories;
  for (const std::vector<char>& theirs : Utilities::MPI::all_gather(d.comm, states))
    for (std::size_t at = 0; at + record <= theirs.size(); at += record)
    {
      double c[3];
      std::memcpy(c, theirs.data() + at, 3 * sizeof(double));
      std::vector<materials::PointState> s(old.n_q_points);
      std::memcpy(s.data(), theirs.data() + at + 3 * sizeof(double),
                  old.n_q_points * sizeof(materials::PointState));
      histories[key_of(Point<3>(c[0], c[1], c[2]), quantum)] = std::move(s);
    }
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (cell->is_locally_owned() && missing.empty())
    {
      const auto found = histories.find(key_of(cell->center(), quantum));
      if (found == histories.end() || found->second.size() != d.n_q_points)
      {
        missing = "a cell of the new far-field mesh has no counterpart in the old one";
        break;
      }
      std::copy(found->second.begin(), found->second.end(),
                d.committed_states.begin() + std::size_t(cell->active_cell_index()) * d.n_q_points);
    }
  if (Utilities::MPI::max(missing.empty() ? 0u : 1u, d.comm) > 0)
    throw std::logic_error("adaptive zone: " +
                           (missing.empty() ? std::string("a mesh mismatch on another rank") : missing));
  d.trial_states = d.committed_states;
  for (Data::Vector* v : {&d.displacement, &d.velocity, &d.acceleration})
    v->compress(VectorOperation::insert);

  d.time = old.time;
  d.step = old.step;
  d.external_work = old.external_work;
  d.dissipated_energy = old.dissipated_energy;
  d.last_warned_failures = old.last_warned_failures;
  d.n_failed_points = old.n_failed_points;
  d.phase_times = old.phase_times;
  // The supports' impulses are summed over ranks when read: the total goes to rank 0.
  const bool first_rank = Utilities::MPI::this_mpi_process(d.comm) == 0;
  for (unsigned int b = 0; b <= n_slab_faces; ++b)
  {
    const Tensor<1, 3> total = Utilities::MPI::sum(old.support_impulse[b], d.comm);
    d.support_impulse[b] = first_rank ? total : Tensor<1, 3>();
  }

  // Forces at the taken-over state; an implicit integrator keeps its own accelerations.
  const Data::Vector acceleration = d.acceleration;
  evaluate_explicit_forces(d.time);
  if (d.is_implicit())
    d.acceleration = acceleration;
  d.inertia_coupling_raw = 0.0;
  for (unsigned int n = 0; n < d.interface_nodes.size(); ++n)
    d.interface_velocity_targets[n] = velocity(d.interface_nodes[n]);
  d.boundary_now = d.boundary_forces();
  d.interface_impulse_last_step.assign(d.interface_nodes.size(), Tensor<1, 3>());
  d.last_power = d.external_power();
}
} // namespace vulnus::fem
