// FarFieldSolver set-up (mesh, dofs, hanging-node and face constraints, node lists, lumped
// mass, initial state), accessors, coupling hooks and diagnostics.
#include "fem/far_field_solver.h"

#include "fem/far_field_data.h"
#include "fem/mesh_builder.h"
#include "fem/tensor_conversion.h"
#include "materials/material_registry.h"

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace vulnus::fem
{
using namespace dealii;

void throw_if_any(const bool failed, const std::string& message, const MPI_Comm comm)
{
  if (Utilities::MPI::max(failed ? 1 : 0, comm) == 0)
    return;
  // Every rank throws the first failing rank's own words: a rank whose cells were fine has no
  // message of its own to give.
  const std::vector<std::string> messages =
    Utilities::MPI::all_gather(comm, failed ? "1" + message : std::string("0"));
  for (std::size_t rank = 0; rank < messages.size(); ++rank)
  {
    if (messages[rank][0] != '1')
      continue;
    std::string what = messages[rank].substr(1);
    if (what.empty())
      what = "a far-field failure that gave no message";
    if (!failed)
      what = "on MPI rank " + std::to_string(rank) + ": " + what;
    throw std::runtime_error(what);
  }
}

FarFieldSolver::Data::Data(const FeSceneParameters& parameters, const MPI_Comm communicator)
    : prm(parameters), comm(communicator),
      material(materials::create_material(parameters.material)),
      owned_triangulation(Utilities::MPI::n_mpi_processes(communicator) == 1
                            ? std::make_unique<Triangulation<3>>()
                            : std::make_unique<parallel::distributed::Triangulation<3>>(communicator)),
      triangulation(*owned_triangulation),
      fe(FE_Q<3>(parameters.degree), 3), dof_handler(triangulation),
      quadrature(parameters.one_point_integration ? 1 : parameters.degree + 1),
      mass_quadrature(parameters.degree + 1), face_quadrature(parameters.degree + 1)
{
}

double FarFieldSolver::Data::dirichlet_velocity(const DirichletDof& d, const double t) const
{
  switch (d.source)
  {
  case DirichletSource::zero:
    return 0.0;
  case DirichletSource::face_constant:
    return prm.faces[d.index].value[d.component] * prm.faces[d.index].profile.value(t);
  case DirichletSource::face_field:
    return face_fields[d.index](d.position, t)[d.component];
  case DirichletSource::interface:
    return interface_velocity_targets[d.index][d.component];
  }
  return 0.0;
}

FarFieldSolver::FarFieldSolver(const FeSceneParameters& parameters, const MPI_Comm communicator)
{
  require_valid(parameters);
  data = std::make_unique<Data>(parameters, communicator);
}

FarFieldSolver::~FarFieldSolver() = default;

void FarFieldSolver::set_face_velocity_field(const types::boundary_id face,
                                             const TimeVectorFunction& velocity)
{
  AssertThrow(face < n_slab_faces, ExcMessage("set_face_velocity_field: face id must be 0-5"));
  data->face_fields[face] = velocity;
}

namespace
{
/// Priority of a Dirichlet condition on one dof: higher wins.
struct DirichletCandidate
{
  int priority = 0;
  DirichletDof dof{};
};

using Data = FarFieldSolver::Data;
using NodeOfDof = std::unordered_map<types::global_dof_index, unsigned int>;

/// Dofs, the owned and relevant index sets, and the hanging-node constraints.
void distribute_dofs(Data& d)
{
  d.dof_handler.distribute_dofs(d.fe);
  d.owned_dofs = d.dof_handler.locally_owned_dofs();
  d.relevant_dofs = DoFTools::extract_locally_relevant_dofs(d.dof_handler);
  d.hanging_constraints.clear();
  d.hanging_constraints.reinit(d.relevant_dofs);
  DoFTools::make_hanging_node_constraints(d.dof_handler, d.hanging_constraints);
  d.hanging_constraints.close();
}

/// Nodes owned by this rank and held by a live cell; returns the node of each of their dofs.
/// Owned cells come first; a node whose only live cells are ghosts (its owned cells were
/// converted) follows from those.
NodeOfDof collect_owned_nodes(Data& d)
{
  std::vector<types::global_dof_index> dofs(d.fe.n_dofs_per_cell());
  const std::vector<Point<3>>& unit_points = d.fe.base_element(0).get_unit_support_points();
  d.owned_nodes.clear();
  std::unordered_map<types::global_dof_index, unsigned int> node_of_dof;
  for (const bool owned_cells : {true, false})
    for (const auto& cell : d.dof_handler.active_cell_iterators())
    {
      if (cell->is_artificial() || d.is_converted(cell) || cell->is_locally_owned() != owned_cells)
        continue;
      cell->get_dof_indices(dofs);
      for (unsigned int j = 0; j < unit_points.size(); ++j)
      {
        NodeRecord node;
        for (unsigned int c = 0; c < 3; ++c)
          node.dofs[c] = dofs[d.fe.component_to_system_index(c, j)];
        if (!d.owned_dofs.is_element(node.dofs[0]) || node_of_dof.count(node.dofs[0]) > 0)
          continue;
        node.position = d.mapping.transform_unit_to_real_cell(cell, unit_points[j]);
        for (unsigned int c = 0; c < 3; ++c)
          node_of_dof[node.dofs[c]] = d.owned_nodes.size();
        d.owned_nodes.push_back(node);
      }
    }

  return node_of_dof;
}

/// The dofs of every boundary face (owned ones, by face) and the Dirichlet condition that wins
/// on each locally relevant dof.
std::map<types::global_dof_index, DirichletCandidate> collect_face_dofs_and_supports(Data& d)
{
  const FeSceneParameters& prm = d.prm;
  const unsigned int dofs_per_face = d.fe.n_dofs_per_face();
  std::vector<types::global_dof_index> face_dof_indices(dofs_per_face);
  std::map<types::global_dof_index, DirichletCandidate> candidates;
  for (auto& list : d.face_dofs)
    list.clear();
  std::vector<std::set<types::global_dof_index>> face_sets(n_slab_faces + 1);
  const bool interface_driven = prm.interface_condition == InterfaceCondition::velocity_driven;
  for (const auto& cell : d.dof_handler.active_cell_iterators())
    if (!cell->is_artificial() && !d.is_converted(cell))
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() || d.is_converted(cell->neighbor(f)))
        {
          // A face next to a converted cell is a face of the grown hole.
          const types::boundary_id b = cell->face(f)->at_boundary() ? cell->face(f)->boundary_id()
                                                                    : boundary_ids::interface;
          if (b > boundary_ids::interface)
            continue;
          cell->face(f)->get_dof_indices(face_dof_indices);
          for (unsigned int k = 0; k < dofs_per_face; ++k)
          {
            const types::global_dof_index dof = face_dof_indices[k];
            const unsigned int component = d.fe.face_system_to_component_index(k).first;
            if (d.owned_dofs.is_element(dof) &&
                face_sets[b].insert(dof).second)
              d.face_dofs[b].emplace_back(dof, component);
            if (d.hanging_constraints.is_constrained(dof))
              continue;
            DirichletCandidate candidate;
            candidate.dof = {dof, component, DirichletSource::zero, 0u, Point<3>(), b};
            if (b == boundary_ids::interface)
            {
              if (!interface_driven)
                continue;
              candidate.priority = 3;
              candidate.dof.source = DirichletSource::interface;
            }
            else if (d.face_fields[b])
            {
              candidate.priority = 2;
              candidate.dof.source = DirichletSource::face_field;
              candidate.dof.index = b;
            }
            else
              switch (prm.faces[b].condition)
              {
              case FaceParameters::Condition::fixed:
                candidate.priority = 4;
                break;
              case FaceParameters::Condition::velocity:
                candidate.priority = 2;
                candidate.dof.source = DirichletSource::face_constant;
                candidate.dof.index = b;
                break;
              case FaceParameters::Condition::roller:
                if (component != b / 2)
                  continue;
                candidate.priority = 1;
                break;
              default:
                continue;
              }
            DirichletCandidate& current = candidates[dof];
            // Two zero conditions on an edge or corner hold the dof alike; its reaction is
            // booked on the face normal to its component (the z- face's normal reaction at
            // the x-/z- edge is the z- face's, whichever face came first).
            const bool normal_of_equal_zero =
              candidate.priority == current.priority &&
              candidate.dof.source == DirichletSource::zero &&
              current.dof.source == DirichletSource::zero && b / 2 == component;
            if (candidate.priority > current.priority || normal_of_equal_zero)
              current = candidate;
          }
        }

  return candidates;
}

/// Owned nodes on the hole surface; returns the interface index of each of their dofs.
NodeOfDof collect_interface_nodes(Data& d, const NodeOfDof& node_of_dof)
{
  d.interface_nodes.clear();
  std::unordered_map<types::global_dof_index, unsigned int> interface_index_of_dof;
  for (const auto& [dof, component] : d.face_dofs[boundary_ids::interface])
    if (component == 0)
    {
      const NodeRecord& node = d.owned_nodes[node_of_dof.at(dof)];
      for (unsigned int c = 0; c < 3; ++c)
        interface_index_of_dof[node.dofs[c]] = d.interface_nodes.size();
      d.interface_nodes.push_back(node);
    }
  d.interface_velocity_targets.assign(d.interface_nodes.size(), Tensor<1, 3>());

  return interface_index_of_dof;
}

/// The constraints of the increments (hanging nodes and every Dirichlet dof) and the list of
/// owned Dirichlet dofs with their sources.
void build_dirichlet_constraints(Data& d,
                                 std::map<types::global_dof_index, DirichletCandidate>& candidates,
                                 const NodeOfDof& node_of_dof, const NodeOfDof& interface_index_of_dof)
{
  d.increment_constraints.clear();
  d.increment_constraints.reinit(d.relevant_dofs);
  d.increment_constraints.merge(d.hanging_constraints);
  d.dirichlet_dofs.clear();
  d.dead_dofs.clear();
  if (d.n_converted_cells > 0)
  {
    // Every cell holding an owned dof is owned or a ghost, so the live ones tell which owned
    // dofs are dead (a ghost dof on the ghost layer's rim may be marked dead without being so;
    // only owned rows and owned cells use these lines).
    std::vector<char> live(d.relevant_dofs.n_elements(), 0);
    std::vector<types::global_dof_index> dofs(d.fe.n_dofs_per_cell());
    for (const auto& cell : d.dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && !d.is_converted(cell))
      {
        cell->get_dof_indices(dofs);
        for (const auto i : dofs)
          live[d.relevant_dofs.index_within_set(i)] = 1;
      }
    for (const auto i : d.relevant_dofs)
      if (!live[d.relevant_dofs.index_within_set(i)])
      {
        d.increment_constraints.add_line(i);
        if (d.owned_dofs.is_element(i))
          d.dead_dofs.push_back(i);
      }
  }
  for (auto& [dof, candidate] : candidates)
  {
    d.increment_constraints.add_line(dof);
    if (!d.owned_dofs.is_element(dof))
      continue;
    DirichletDof entry = candidate.dof;
    entry.position = d.owned_nodes[node_of_dof.at(dof)].position;
    if (entry.source == DirichletSource::interface)
      entry.index = interface_index_of_dof.at(dof);
    d.dirichlet_dofs.push_back(entry);
  }
  d.increment_constraints.close();
}

/// The solution and work vectors on the owned (and relevant) dofs.
void allocate_vectors(Data& d)
{
  for (Data::Vector* v :
       {&d.displacement, &d.velocity, &d.acceleration, &d.lumped_mass, &d.inverse_mass,
        &d.internal_force_raw, &d.external_force_raw, &d.inertia_coupling_raw, &d.residual})
    v->reinit(d.owned_dofs, d.comm);
  d.ghosted.reinit(d.owned_dofs, d.relevant_dofs, d.comm);
  d.ghosted_velocity.reinit(d.ghosted);
  d.cell_local_dofs.clear(); // indices into the old layout
}

/// Quadrature-point history, fibers and cell sizes.
void build_point_history(Data& d)
{
  const FeSceneParameters& prm = d.prm;
  d.n_q_points = d.quadrature.size();
  const unsigned int n_cells = d.triangulation.n_active_cells();
  d.committed_states.assign(std::size_t(n_cells) * d.n_q_points, materials::PointState());
  d.trial_states = d.committed_states;
  d.fiber_directions.assign(d.committed_states.size(), Eigen::Vector3d::UnitX());
  d.cell_stress.assign(n_cells, Tensor<2, 3>());
  d.cell_failure.assign(n_cells, 0);
  d.cell_wave_speed.assign(n_cells, 0.0);
  d.cell_failure_proximity.assign(n_cells, 0.0);
  d.cell_size.assign(n_cells, 0.0);
  FEValues<3> fe_values(d.mapping, d.fe, d.quadrature, update_quadrature_points);
  const bool fibers = d.material->uses_fibers();
  for (const auto& cell : d.dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      const std::size_t first = std::size_t(cell->active_cell_index()) * d.n_q_points;
      if (fibers)
      {
        fe_values.reinit(cell);
        for (unsigned int q = 0; q < d.n_q_points; ++q)
        {
          const Point<3>& x = fe_values.quadrature_point(q);
          d.fiber_directions[first + q] =
              materials::fiber_direction(prm.fibers, Eigen::Vector3d(x[0], x[1], x[2]));
        }
      }
      d.cell_size[cell->active_cell_index()] = cell->minimum_vertex_distance() / prm.degree;
    }
}

/// Lumped (row-sum) mass m_i = int rho0 N_i over the live cells and its inverse (zero on
/// constrained, Dirichlet and dead dofs).
void build_lumped_mass(Data& d)
{
  const unsigned int dofs_per_cell = d.fe.n_dofs_per_cell();
  std::vector<types::global_dof_index> dofs(dofs_per_cell);
  FEValues<3> fe_values(d.mapping, d.fe, d.mass_quadrature, update_values | update_JxW_values);
  Vector<double> local_mass(dofs_per_cell);
  d.lumped_mass = 0.0;
  for (const auto& cell : d.dof_handler.active_cell_iterators())
    if (d.owns_live(cell))
    {
      fe_values.reinit(cell);
      cell->get_dof_indices(dofs);
      local_mass = 0.0;
      for (unsigned int q = 0; q < d.mass_quadrature.size(); ++q)
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          local_mass(i) +=
              d.prm.density *
              fe_values.shape_value_component(i, q, d.fe.system_to_component_index(i).first) *
              fe_values.JxW(q);
      d.hanging_constraints.distribute_local_to_global(local_mass, dofs, d.lumped_mass);
    }
  d.lumped_mass.compress(VectorOperation::add);
  for (const auto i : d.owned_dofs)
  {
    const double m = d.lumped_mass(i);
    d.inverse_mass(i) = (m > 0.0 && !d.hanging_constraints.is_constrained(i)) ? 1.0 / m : 0.0;
  }
  for (const DirichletDof& dirichlet : d.dirichlet_dofs)
    d.inverse_mass(dirichlet.dof) = 0.0;
  d.inverse_mass.compress(VectorOperation::insert);
  d.dead_dof_mass = d.lumped_mass.l1_norm() / std::max(double(d.dof_handler.n_dofs()), 1.0);
  d.n_dead_dofs = Utilities::MPI::sum(static_cast<unsigned long long>(d.dead_dofs.size()), d.comm);
}
} // namespace

void build_boundaries_and_mass(FarFieldSolver::Data& d)
{
  const NodeOfDof node_of_dof = collect_owned_nodes(d);
  std::map<types::global_dof_index, DirichletCandidate> candidates = collect_face_dofs_and_supports(d);
  const NodeOfDof interface_index_of_dof = collect_interface_nodes(d, node_of_dof);
  build_dirichlet_constraints(d, candidates, node_of_dof, interface_index_of_dof);
  build_lumped_mass(d);
}

void FarFieldSolver::setup(const std::function<void(Triangulation<3, 3>&)>& modify_mesh)
{
  Data& d = *data;
  build_slab_mesh(d.prm, d.triangulation);
  if (modify_mesh)
    modify_mesh(d.triangulation);
  distribute_dofs(d);
  d.cell_converted.clear();
  d.n_converted_cells = 0;
  allocate_vectors(d);
  build_point_history(d);
  build_boundaries_and_mass(d);

  // Initial state: u = 0, v = prescribed values, a = M^{-1} (f_ext - f_int).
  d.time = 0.0;
  d.step = 0;
  for (const DirichletDof& dirichlet : d.dirichlet_dofs)
    d.velocity(dirichlet.dof) = d.dirichlet_velocity(dirichlet, 0.0);
  d.velocity.compress(VectorOperation::insert);
  d.skip_quiet_cells = false;
  evaluate_explicit_forces(0.0);
  d.skip_quiet_cells = d.prm.skip_quiet_cells;
  d.last_power = d.external_power();
  d.boundary_now = d.boundary_forces();
  d.reset_booked_dirichlet_velocities();
  d.interface_impulse_last_step.assign(d.interface_nodes.size(), Tensor<1, 3>());
  d.support_impulse = {};
}

void FarFieldSolver::set_initial_velocity(const VectorFunction& velocity)
{
  Data& d = *data;
  for (const NodeRecord& node : d.owned_nodes)
  {
    const Tensor<1, 3> v = velocity(node.position);
    for (unsigned int c = 0; c < 3; ++c)
      d.velocity(node.dofs[c]) = v[c];
  }
  // A velocity-driven interface starts from (and holds) the initial field until set.
  for (unsigned int n = 0; n < d.interface_nodes.size(); ++n)
    d.interface_velocity_targets[n] = velocity(d.interface_nodes[n].position);
  for (const DirichletDof& dirichlet : d.dirichlet_dofs)
    d.velocity(dirichlet.dof) = d.dirichlet_velocity(dirichlet, d.time);
  d.velocity.compress(VectorOperation::insert);
  d.hanging_constraints.distribute(d.velocity);
  d.last_power = d.external_power();
}

double FarFieldSolver::next_time_step() const
{
  const Data& d = *data;
  if (d.is_implicit())
    return d.prm.time_step;
  const double transit = shortest_wave_transit();
  AssertThrow(std::isfinite(transit),
              ExcMessage("FE: no far-field cell carries stress any more (every live cell has "
                         "failed, or none is left), so no stable time step exists: the wound "
                         "has reached the whole far field; enlarge the MPM zone (Hybrid/Zone "
                         "min, Zone max, or Hybrid/Adaptive zone with a reach to the slab's "
                         "faces) or run the scene as pure MPM"));
  return d.prm.cfl * transit;
}

double FarFieldSolver::shortest_wave_transit() const
{
  const Data& d = *data;
  double transit = std::numeric_limits<double>::infinity();
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (d.owns_live(cell))
    {
      const unsigned int k = cell->active_cell_index();
      if (d.cell_wave_speed[k] > 0.0)
        transit = std::min(transit, d.cell_size[k] / d.cell_wave_speed[k]);
    }
  return Utilities::MPI::min(transit, d.comm);
}

void FarFieldSolver::advance(const double dt)
{
  AssertThrow(dt > 0.0 && std::isfinite(dt), ExcMessage("FE advance: time step must be positive"));
  if (data->is_implicit())
  {
    advance_implicit(dt);
    data->integrate_boundary_forces(dt);
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  const double forces_before = data->phase_times.internal_forces;
  advance_explicit(dt);
  data->integrate_boundary_forces(dt);
  FePhaseTimes& t = data->phase_times;
  const double step_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.rest += step_seconds - (t.internal_forces - forces_before);
  ++t.n_steps;
}

const FePhaseTimes& FarFieldSolver::explicit_phase_times() const
{
  return data->phase_times;
}

double FarFieldSolver::time() const
{
  return data->time;
}
unsigned int FarFieldSolver::step_number() const
{
  return data->step;
}
const FeSceneParameters& FarFieldSolver::parameters() const
{
  return data->prm;
}
MPI_Comm FarFieldSolver::communicator() const
{
  return data->comm;
}
const ImplicitStepStatistics& FarFieldSolver::last_implicit_step() const
{
  return data->implicit_statistics;
}
unsigned long long FarFieldSolver::n_failed_points() const
{
  return data->n_failed_points;
}
unsigned long long FarFieldSolver::n_active_cells() const
{
  return data->triangulation.n_global_active_cells() - data->n_converted_cells;
}
unsigned long long FarFieldSolver::n_dofs() const
{
  return data->dof_handler.n_dofs() - data->n_dead_dofs;
}
unsigned long long FarFieldSolver::n_quadrature_points() const
{
  return n_active_cells() * data->n_q_points;
}
const std::vector<NodeRecord>& FarFieldSolver::locally_owned_nodes() const
{
  return data->owned_nodes;
}
const std::vector<NodeRecord>& FarFieldSolver::interface_nodes() const
{
  return data->interface_nodes;
}

Tensor<1, 3> FarFieldSolver::displacement(const NodeRecord& node) const
{
  Tensor<1, 3> u;
  for (unsigned int c = 0; c < 3; ++c)
    u[c] = data->displacement(node.dofs[c]);
  return u;
}

Tensor<1, 3> FarFieldSolver::velocity(const NodeRecord& node) const
{
  Tensor<1, 3> v;
  for (unsigned int c = 0; c < 3; ++c)
    v[c] = data->velocity(node.dofs[c]);
  return v;
}

void FarFieldSolver::locally_owned_cell_stresses(std::vector<Point<3>>& centres,
                                                 std::vector<Tensor<2, 3>>& stresses) const
{
  centres.clear();
  stresses.clear();
  for (const auto& cell : data->triangulation.active_cell_iterators())
    if (data->owns_live(cell))
    {
      centres.push_back(cell->center());
      stresses.push_back(data->cell_stress[cell->active_cell_index()]);
    }
}

Tensor<2, 3> FarFieldSolver::average_cauchy_stress() const
{
  Tensor<2, 3> sum;
  double volume = 0.0;
  for (const auto& cell : data->triangulation.active_cell_iterators())
    if (data->owns_live(cell))
    {
      const double v = cell->measure();
      sum += v * data->cell_stress[cell->active_cell_index()];
      volume += v;
    }
  sum = Utilities::MPI::sum(sum, data->comm);
  volume = Utilities::MPI::sum(volume, data->comm);
  return sum / volume;
}

std::vector<double> FarFieldSolver::interface_lumped_masses() const
{
  std::vector<double> masses;
  for (const NodeRecord& node : data->interface_nodes)
    masses.push_back(data->lumped_mass(node.dofs[0]));
  return masses;
}

const std::vector<Tensor<1, 3>>& FarFieldSolver::interface_nodal_forces() const
{
  return data->boundary_now.interface;
}

const std::vector<Tensor<1, 3>>& FarFieldSolver::interface_impulses_of_last_step() const
{
  return data->interface_impulse_last_step;
}

std::vector<Tensor<1, 3>> FarFieldSolver::interface_reactions() const
{
  std::vector<Tensor<1, 3>> reactions;
  for (std::size_t n = 0; n < data->interface_nodes.size(); ++n)
  {
    Tensor<1, 3> r = -data->boundary_now.interface[n];
    for (unsigned int c = 0; c < 3; ++c)
    {
      const auto i = data->interface_nodes[n].dofs[c];
      r[c] += data->lumped_mass(i) * data->acceleration(i);
    }
    reactions.push_back(r);
  }
  return reactions;
}

void FarFieldSolver::set_interface_velocities(const std::vector<Tensor<1, 3>>& velocities)
{
  AssertThrow(data->prm.interface_condition == InterfaceCondition::velocity_driven,
              ExcMessage("set_interface_velocities: the interface is not velocity driven"));
  AssertThrow(velocities.size() == data->interface_nodes.size(),
              ExcMessage("set_interface_velocities: one velocity per interface node expected"));
  data->interface_velocity_targets = velocities;
}

FeDiagnostics FarFieldSolver::diagnostics() const
{
  const Data& d = *data;
  FeDiagnostics r;
  r.time = d.time;
  r.step = d.step;
  r.kinetic_energy = d.kinetic_energy();
  r.strain_energy = Utilities::MPI::sum(d.last_sums.strain_energy, d.comm);
  r.external_work = d.external_work;
  r.external_work_in = d.external_work_in;
  r.dissipated_energy = d.dissipated_energy;
  Tensor<1, 3> momentum;
  for (const NodeRecord& node : d.owned_nodes)
    for (unsigned int c = 0; c < 3; ++c)
      momentum[c] += d.lumped_mass(node.dofs[c]) * d.velocity(node.dofs[c]);
  r.momentum = Utilities::MPI::sum(momentum, d.comm);
  for (unsigned int b = 0; b <= n_slab_faces; ++b)
  {
    Tensor<1, 3> reaction;
    for (const auto& [dof, component] : d.face_dofs[b])
      reaction[component] += d.lumped_mass(dof) * d.acceleration(dof) + d.internal_force_raw(dof) -
                             d.external_force_raw(dof);
    r.face_reactions[b] = Utilities::MPI::sum(reaction, d.comm);
    r.support_impulses[b] = Utilities::MPI::sum(d.support_impulse[b], d.comm);
  }
  r.n_failed_points = d.n_failed_points;
  double c_max = 0.0;
  for (const auto& cell : d.triangulation.active_cell_iterators())
    if (d.owns_live(cell))
      c_max = std::max(c_max, d.cell_wave_speed[cell->active_cell_index()]);
  r.max_wave_speed = Utilities::MPI::max(c_max, d.comm);
  return r;
}
} // namespace vulnus::fem
