// The far field's side of an adaptive MPM zone: which cells near failure (kept by every force
// evaluation), the material points of cells about to convert (and of failed cells, for the wound
// figures), and their conversion: the cells stay in the mesh, switched off, and the faces they
// share with live cells join the interface.
#include "fem/far_field_data.h"
#include "fem/tensor_conversion.h"
#include "fem/volume_averaged_cell.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace vulnus::fem
{
using namespace dealii;

namespace
{
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

/// Points of a far field's cell need linear elements, each Gauss point owning an octant.
void require_linear_elements(const FarFieldSolver::Data& d)
{
  AssertThrow(d.prm.degree == 1 && (d.n_q_points == 8 || d.n_q_points == 1),
              ExcMessage("material points from a far field need linear elements"));
}

/// The Gauss point (2 x 2 x 2 Gauss, x fastest) in the octant of the unit-cell point xi, or the
/// one point; a point on a mid-plane takes the lower octant's.
unsigned int gauss_point_of_octant(const Point<3>& xi, const unsigned int n_q_points)
{
  return n_q_points == 1 ? 0 : (xi[0] > 0.5) + 2 * (xi[1] > 0.5) + 4 * (xi[2] > 0.5);
}

/// A cell belongs to a box when its centre lies strictly inside (box faces are mesh planes).
bool centre_inside(const Point<3>& c, const std::array<double, 3>& box_min,
                   const std::array<double, 3>& box_max)
{
  for (unsigned int a = 0; a < 3; ++a)
    if (!(c[a] > box_min[a] && c[a] < box_max[a]))
      return false;
  return true;
}
} // namespace

std::vector<Point<3>> FarFieldSolver::cells_nearing_failure(const double threshold) const
{
  const Data& d = *data;
  AssertThrow(d.prm.track_failure_proximity,
              ExcMessage("cells_nearing_failure needs FeSceneParameters::track_failure_proximity"));
  std::vector<double> mine;
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (d.owns_live(cell) && d.cell_failure_proximity[cell->active_cell_index()] >= threshold)
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
  require_linear_elements(d);
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
    if (!d.owns_live(cell) || !centre_inside(cell->center(), box_min, box_max))
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(dofs);
    evaluate_cell(fe_values, dofs, u, v, d.fe, k);
    if (d.prm.volume_averaging)
    {
      // The points take F_bar, as the law saw it: the cell's mean J (fem/volume_averaged_cell.h).
      std::vector<Eigen::Matrix3d> F(k.F.size()), F_bar(k.F.size());
      std::vector<double> w(k.F.size());
      for (std::size_t q = 0; q < k.F.size(); ++q)
      {
        F[q] = to_eigen(k.F[q]);
        w[q] = fe_values.JxW(q);
      }
      volume_averaged_gradients(int(F.size()), F.data(), w.data(), F_bar.data());
      for (std::size_t q = 0; q < k.F.size(); ++q)
        k.F[q] = to_dealii(F_bar[q]);
    }
    const std::size_t first = std::size_t(cell->active_cell_index()) * d.n_q_points;
    for (unsigned int q = 0; q < lattice.size(); ++q)
    {
      // The history of the Gauss point in the same octant.
      const unsigned int gauss = gauss_point_of_octant(lattice.point(q), d.n_q_points);
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

void FarFieldSolver::convert_cells_inside(const std::array<double, 3>& box_min,
                                          const std::array<double, 3>& box_max)
{
  Data& d = *data;
  AssertThrow(d.triangulation.n_global_levels() == 1,
              ExcMessage("converting far-field cells needs an unrefined mesh"));
  if (d.cell_converted.empty())
    d.cell_converted.assign(d.triangulation.n_active_cells(), 0);
  // Every rank holds every cell of the unrefined mesh (artificial ones too), so each decides
  // all of them alike, ghosts and neighbours across ranks included.
  for (const auto& cell : d.triangulation.active_cell_iterators())
  {
    unsigned char& converted = d.cell_converted[cell->active_cell_index()];
    if (!converted && centre_inside(cell->center(), box_min, box_max))
    {
      converted = 1;
      ++d.n_converted_cells;
    }
  }
  build_boundaries_and_mass(d);
  for (const auto dof : d.dead_dofs)
  {
    d.velocity(dof) = 0.0;
    d.acceleration(dof) = 0.0;
  }
  for (Data::Vector* v : {&d.velocity, &d.acceleration})
    v->compress(VectorOperation::insert);
  d.implicit.reset(); // its sparsity and constraints were those of the smaller hole
  d.cell_local_dofs.clear(); // and the live cells with them

  // Forces at the current state on the new mass; an implicit integrator keeps its own
  // accelerations, and Dirichlet dofs keep theirs (the evaluation gives them none). The
  // converted cells' histories are no longer evaluated: trial = committed keeps the commits'
  // swap from alternating them.
  d.trial_states = d.committed_states;
  const Data::Vector acceleration = d.acceleration;
  evaluate_explicit_forces(d.time);
  if (d.is_implicit())
    d.acceleration = acceleration;
  else
  {
    for (const DirichletDof& dirichlet : d.dirichlet_dofs)
      d.acceleration(dirichlet.dof) = acceleration(dirichlet.dof);
    d.acceleration.compress(VectorOperation::insert);
  }
  d.inertia_coupling_raw = 0.0;
  for (unsigned int n = 0; n < d.interface_nodes.size(); ++n)
    d.interface_velocity_targets[n] = velocity(d.interface_nodes[n]);
  d.boundary_now = d.boundary_forces();
  d.reset_booked_dirichlet_velocities();
  d.interface_impulse_last_step.assign(d.interface_nodes.size(), Tensor<1, 3>());
  d.last_power = d.external_power();
}
std::vector<FailedLatticePoint> FarFieldSolver::failed_lattice_points(const double spacing) const
{
  const Data& d = *data;
  AssertThrow(spacing > 0.0, ExcMessage("failed_lattice_points needs a positive spacing"));
  require_linear_elements(d);
  std::vector<FailedLatticePoint> points;
  for (const auto& cell : d.dof_handler.active_cell_iterators())
  {
    if (!d.owns_live(cell))
      continue;
    const std::size_t first = std::size_t(cell->active_cell_index()) * d.n_q_points;
    const auto states = d.committed_states.begin() + static_cast<std::ptrdiff_t>(first);
    if (std::all_of(states, states + d.n_q_points,
                    [](const materials::PointState& s) { return s.failure == 0; }))
      continue;
    const unsigned int per_axis = static_cast<unsigned int>(
      std::max(1L, std::lround(cell->extent_in_direction(0) / spacing)));
    const QIterated<3> lattice(QMidpoint<1>(), per_axis);
    FEValues<3> fe_values(d.mapping, d.fe, lattice, update_JxW_values | update_quadrature_points);
    fe_values.reinit(cell);
    for (unsigned int q = 0; q < lattice.size(); ++q)
    {
      const unsigned int gauss = gauss_point_of_octant(lattice.point(q), d.n_q_points);
      const std::uint8_t failure = states[gauss].failure;
      if (failure != 0)
        points.push_back({fe_values.quadrature_point(q), fe_values.JxW(q), failure,
                          d.cell_stress[cell->active_cell_index()]});
    }
  }
  return points;
}
} // namespace vulnus::fem
