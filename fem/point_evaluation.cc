// Quadrature-point work of the far field: deformation gradients, material updates with the
// per-point history, the explicit step's shock viscosity, internal forces f_int = int P : grad
// N dV, cell stress, failure and wave speed; external forces (tractions, interface forces);
// energies and external power.
#include "fem/far_field_data.h"
#include "fem/tensor_conversion.h"
#include "fem/volume_averaged_cell.h"
#include "materials/two_surface_failure.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <cmath>
#include <limits>
#include <iostream>
#include <stdexcept>

namespace vulnus::fem
{
using namespace dealii;

namespace
{
/// What one cell's pass gives the assembly, kept per cell so that the threads' work is added
/// in cell order (results independent of the thread count).
struct CellForces
{
  double strain_energy = 0.0;
  double dissipated = 0.0;
  bool evaluated = false;
};
} // namespace

EvaluationSums FarFieldSolver::Data::evaluate_internal_forces(const Vector& u_ghosted,
                                                              Vector* condensed,
                                                              const Vector* v_ghosted)
{
  const unsigned int n_dofs = fe.n_dofs_per_cell();
  const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();

  const materials::FailureParameters* criterion = proximity_criterion();
  const bool fibers = material->uses_fibers();
  const bool average_volume = prm.volume_averaging && n_q_points > 1;
  internal_force_raw = 0.0;
  if (cell_local_dofs.empty())
    index_cell_dofs(u_ghosted);
  const double* u_values = u_ghosted.trilinos_vector()[0];
  const double* v_values = v_ghosted != nullptr ? v_ghosted->trilinos_vector()[0] : nullptr;
  const long n_live = static_cast<long>(live_cells.size());
  std::vector<CellForces> results(live_cells.size());
  cell_force_values.resize(live_cells.size() * n_dofs);
  long first_failed = n_live;
  std::string message;
  std::exception_ptr unexpected;
  unsigned long long quiet_skipped = 0;

  struct Scratch
  {
    std::vector<double> u_local, v_local;
    materials::PointResponse response;
    std::vector<Eigen::Matrix3d> F, F_law, sigma, P;
    std::vector<double> JxW;
    std::vector<double> volume_rate; ///< d ln J / dt of the law's J, per point
  };
  // Records the failure of live cell c: the first in cell order is reported.
  auto record_failure = [&](const long c, const std::string& what, std::exception_ptr error)
  {
#pragma omp critical(far_field_failed_cell)
    if (c < first_failed)
    {
      first_failed = c;
      const Point<3> x = live_cells[c]->center();
      message = "FE: " + what + " in the cell at " + std::to_string(x[0]) + " " +
                std::to_string(x[1]) + " " + std::to_string(x[2]) + " m";
      unexpected = error;
    }
  };
  // The rate of the law's volume change at each point, d ln J / dt = tr(F_dot F^-1), or with
  // the cell's mean J that of J_bar, sum J tr(L) JxW / sum J JxW (needs w.F, w.JxW, w.v_local).
  auto volume_rates = [&](const CellShape& shape, Scratch& w, const bool cell_mean)
  {
    double rate_volume = 0.0, volume = 0.0;
    for (unsigned int q = 0; q < n_q_points; ++q)
    {
      Eigen::Matrix3d F_dot = Eigen::Matrix3d::Zero();
      for (unsigned int i = 0; i < n_dofs; ++i)
        F_dot.row(dof_component[i]) +=
          w.v_local[i] * shape.gradients[q * n_nodes + dof_node[i]].transpose();
      w.volume_rate[q] = (F_dot * w.F[q].inverse()).trace();
      const double current_volume = w.F[q].determinant() * w.JxW[q];
      rate_volume += w.volume_rate[q] * current_volume;
      volume += current_volume;
    }
    if (cell_mean)
      std::fill(w.volume_rate.begin(), w.volume_rate.end(), rate_volume / volume);
  };
  // One live cell's forces, energies, stress, failure, wave speed and failure proximity.
  enum class Outcome { evaluated, quiet, failed };
  auto evaluate_cell = [&](const long c, Scratch& w) -> Outcome
  {
    const auto& cell = live_cells[c];
    const unsigned int k = cell->active_cell_index();
    const std::size_t first = std::size_t(k) * n_q_points;
    const int* local = &cell_local_dofs[std::size_t(k) * n_dofs];
    for (unsigned int i = 0; i < n_dofs; ++i)
      w.u_local[i] = u_values[local[i]];
    if (skip_quiet_cells && is_quiet(w.u_local, cell_size[k], first))
    {
      // Its forces, energy and stress are those of the rest state, to a strain of 1e-12.
      std::copy_n(committed_states.begin() + first, n_q_points, trial_states.begin() + first);
      std::fill_n(&cell_force_values[std::size_t(c) * n_dofs], n_dofs, 0.0);
      return Outcome::quiet;
    }
    const CellShape& shape = cell_shapes[live_cell_shape[c]];
    const Eigen::Vector3d* grads = shape.gradients.data(); // [q * n_nodes + a]
    double* f_local = &cell_force_values[std::size_t(c) * n_dofs];
    std::fill_n(f_local, n_dofs, 0.0);
    CellForces& r = results[c];
    Tensor<2, 3> stress_sum;
    double volume = 0.0, c_max = 0.0, proximity = 0.0;
    unsigned char flags = 0;
    for (unsigned int q = 0; q < n_q_points; ++q)
    {
      Eigen::Matrix3d& F = w.F[q];
      F.setIdentity();
      for (unsigned int i = 0; i < n_dofs; ++i)
        F.row(dof_component[i]) += w.u_local[i] * grads[q * n_nodes + dof_node[i]].transpose();
      w.JxW[q] = shape.jxw[q];
    }
    // The law sees F, or F_bar with the cell's mean dilatation (fem/volume_averaged_cell.h);
    // one point is its own cell mean.
    double j_bar = 0.0;
    try
    {
      if (average_volume)
        j_bar = volume_averaged_gradients(n_q_points, w.F.data(), w.JxW.data(), w.F_law.data());
      else
        std::copy_n(w.F.begin(), n_q_points, w.F_law.begin());
    }
    catch (const std::runtime_error& e)
    {
      record_failure(c, e.what(), nullptr);
      return Outcome::failed;
    }
    if (v_values != nullptr)
    {
      for (unsigned int i = 0; i < n_dofs; ++i)
        w.v_local[i] = v_values[local[i]];
      volume_rates(shape, w, average_volume);
    }
    for (unsigned int q = 0; q < n_q_points; ++q)
    {
      const Eigen::Matrix3d& F_law = w.F_law[q];
      materials::PointState& state = trial_states[first + q];
      state = committed_states[first + q];
      try
      {
        material->update(F_law, fiber_directions[first + q], state, w.response,
                         material_time_step);
      }
      catch (const std::runtime_error& e)
      {
        record_failure(c, e.what(), nullptr);
        return Outcome::failed;
      }
      const double J = F_law.determinant();
      w.sigma[q] = w.response.cauchy_stress;
      double wave_speed = std::sqrt(w.response.p_wave_modulus * J / prm.density);
      if (v_values != nullptr)
        if (const double q_visc = prm.shock_viscosity.pressure(
              prm.density / J, wave_speed, cell_size[k], w.volume_rate[q]);
            q_visc > 0.0)
        {
          w.sigma[q].diagonal().array() -= q_visc;
          r.dissipated += q_visc * -w.volume_rate[q] * J * material_time_step * w.JxW[q];
          wave_speed += std::sqrt(q_visc * J / prm.density);
        }
      if (!average_volume)
        w.P[q] = J * w.sigma[q] * F_law.inverse().transpose();
      const double JxW = w.JxW[q];
      r.strain_energy += w.response.energy_density * JxW;
      r.dissipated += w.response.dissipated_density * JxW;
      stress_sum += JxW * to_dealii(w.sigma[q]);
      volume += JxW;
      c_max = std::max(c_max, wave_speed);
      flags |= state.failure;
      if (criterion != nullptr)
        proximity = std::max(proximity, failure_proximity(*criterion, F_law,
                                                          fibers ? &fiber_directions[first + q]
                                                                 : nullptr,
                                                          state.failure, prm.failure_proximity));
    }
    if (average_volume)
      volume_averaged_stresses(n_q_points, w.F.data(), w.JxW.data(), w.sigma.data(), j_bar,
                               w.P.data());
    for (unsigned int q = 0; q < n_q_points; ++q)
      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const Eigen::Vector3d& grad = grads[q * n_nodes + dof_node[i]];
        const auto row = w.P[q].row(dof_component[i]);
        f_local[i] += (row[0] * grad[0] + row[1] * grad[1] + row[2] * grad[2]) * w.JxW[q];
      }
    if (!shape.hourglass.empty())
    {
      // f_hg = mu S u, stored energy u . f_hg / 2 (fem/hourglass.h).
      double work = 0.0;
      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        const double* row = &shape.hourglass[std::size_t(i) * n_dofs];
        double f = 0.0;
        for (unsigned int j = 0; j < n_dofs; ++j)
          f += row[j] * w.u_local[j];
        f *= hourglass_modulus;
        f_local[i] += f;
        work += f * w.u_local[i];
      }
      r.strain_energy += 0.5 * work;
    }
    cell_stress[k] = stress_sum / volume;
    cell_failure[k] = flags;
    cell_wave_speed[k] = c_max;
    if (criterion != nullptr)
      cell_failure_proximity[k] = proximity;
    return Outcome::evaluated;
  };

  constexpr long chunk = 256;
  const long n_chunks = (n_live + chunk - 1) / chunk;
#pragma omp parallel reduction(+ : quiet_skipped)
  {
    Scratch w;
    w.u_local.resize(n_dofs);
    w.v_local.resize(n_dofs);
    w.volume_rate.resize(n_q_points);
    for (auto* v : {&w.F, &w.F_law, &w.sigma, &w.P})
      v->resize(n_q_points);
    w.JxW.resize(n_q_points);
#pragma omp for schedule(dynamic, 1)
    for (long chunk_index = 0; chunk_index < n_chunks; ++chunk_index)
    {
      const long end = std::min(n_live, (chunk_index + 1) * chunk);
      long c = chunk_index * chunk;
      try
      {
        for (; c < end; ++c)
        {
          const Outcome outcome = evaluate_cell(c, w);
          results[c].evaluated = outcome == Outcome::evaluated;
          quiet_skipped += outcome == Outcome::quiet ? 1 : 0;
        }
      }
      catch (const std::exception& e) // nothing may leave the parallel region
      {
        record_failure(std::min(c, n_live - 1), e.what(), std::current_exception());
      }
      catch (...)
      {
        record_failure(std::min(c, n_live - 1), "unknown error", std::current_exception());
      }
    }
  }
  phase_times.quiet_cells_skipped += quiet_skipped;

  // The cells' forces in cell order, as a serial loop would add them.
  const auto assembly_start = std::chrono::steady_clock::now();
  EvaluationSums sums;
  const bool inverted = first_failed < n_live;
  // Owned dofs gather their cells' forces in cell order on the threads (the sums a serial
  // loop over the cells would make, bit for bit); dofs of other ranks go through add in cell
  // order. Without hanging nodes -f_int goes into *condensed the same way.
  double* f_raw = internal_force_raw.trilinos_vector()[0];
  const bool condense_in_place =
    condensed != nullptr && hanging_constraints.n_constraints() == 0 &&
    condensed->trilinos_vector().Map().PointSameAs(internal_force_raw.trilinos_vector().Map());
  double* f_condensed = condense_in_place ? condensed->trilinos_vector()[0] : nullptr;
  if (!inverted)
  {
    const long n_owned = static_cast<long>(owned_dof_force_begin.size()) - 1;
#pragma omp parallel for schedule(static)
    for (long l = 0; l < n_owned; ++l)
    {
      double sum = f_raw[l];
      double minus_sum = f_condensed != nullptr ? f_condensed[l] : 0.0;
      for (std::size_t e = owned_dof_force_begin[l]; e < owned_dof_force_begin[l + 1]; ++e)
      {
        const double f = cell_force_values[owned_dof_forces[e]]; // zero for a quiet cell
        sum += f;
        minus_sum += -f;
      }
      f_raw[l] = sum;
      if (f_condensed != nullptr)
        f_condensed[l] = minus_sum;
    }
  }
  dealii::Vector<double> f_local(n_dofs);
  std::vector<types::global_dof_index> dofs(n_dofs);
  for (long c = 0; c < n_live && !inverted; ++c)
  {
    if (!results[c].evaluated)
      continue;
    sums.strain_energy += results[c].strain_energy;
    sums.dissipated += results[c].dissipated;
    if (condensed != nullptr && !condense_in_place)
    {
      const double* f = &cell_force_values[std::size_t(c) * n_dofs];
      for (unsigned int i = 0; i < n_dofs; ++i)
        f_local(i) = -f[i];
      live_cells[c]->get_dof_indices(dofs);
      hanging_constraints.distribute_local_to_global(f_local, dofs, *condensed);
    }
  }
  for (std::size_t k = 0; k < ghost_dof_forces.size() && !inverted; ++k)
  {
    const GhostForce& ghost = ghost_dof_forces[k];
    const double f = cell_force_values[ghost.entry], minus_f = -f;
    internal_force_raw.add(1, &ghost.dof, &f);
    if (f_condensed != nullptr)
      condensed->add(1, &ghost.dof, &minus_f);
  }
  internal_force_raw.compress(VectorOperation::add);
  if (condensed != nullptr)
    condensed->compress(VectorOperation::add);
  phase_times.assembly +=
    std::chrono::duration<double>(std::chrono::steady_clock::now() - assembly_start).count();
  if (Utilities::MPI::max(unexpected ? 1 : 0, comm) == 0)
    throw_if_any(inverted, message, comm);
  else
    try
    {
      // The other ranks learn what failed here; this rank keeps its own exception.
      throw_if_any(unexpected != nullptr || inverted, message, comm);
    }
    catch (const std::runtime_error&)
    {
      if (unexpected)
        std::rethrow_exception(unexpected);
      throw;
    }
  return sums;
}

const materials::FailureParameters* FarFieldSolver::Data::proximity_criterion() const
{
  const materials::FailureParameters* criterion =
    prm.track_failure_proximity ? material->failure_criterion() : nullptr;
  return criterion != nullptr && criterion->enabled ? criterion : nullptr;
}

double failure_proximity(const materials::FailureParameters& criterion, const Eigen::Matrix3d& F,
                         const Eigen::Vector3d* fiber, const std::uint8_t failure,
                         const FailureProximity measure)
{
  constexpr double past = std::numeric_limits<double>::infinity();
  const double matrix =
    (failure & materials::matrix_failed)
      ? past
      : materials::matrix_shear_bound(criterion, F) / criterion.matrix_shear_limit;
  if (fiber == nullptr)
    return matrix;
  const double fibers = (failure & materials::fiber_failed)
                          ? past
                          : ((F * *fiber).norm() - 1.0) / (criterion.fiber_stretch_limit - 1.0);
  return measure == FailureProximity::any_failure ? std::max(matrix, fibers)
                                                  : std::min(matrix, fibers);
}

void FarFieldSolver::Data::index_cell_dofs(const Vector& ghosted_layout)
{
  const unsigned int n_dofs = fe.n_dofs_per_cell();
  const Epetra_BlockMap& map = ghosted_layout.trilinos_vector().Map();
  std::vector<types::global_dof_index> dofs(n_dofs);
  cell_local_dofs.assign(std::size_t(triangulation.n_active_cells()) * n_dofs, 0);
  const Epetra_BlockMap& owned_map = internal_force_raw.trilinos_vector().Map();
  live_cells.clear();
  ghost_dof_forces.clear();
  std::vector<int> live_cell_owned_dofs; // position among the owned dofs, -1 if not owned
  bool missing = false;
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    if (!cell->is_locally_owned())
      continue;
    cell->get_dof_indices(dofs);
    if (!is_converted(cell))
    {
      live_cells.push_back(cell);
      for (const auto dof : dofs)
      {
        const int owned = owned_map.LID(static_cast<TrilinosWrappers::types::int_type>(dof));
        if (owned < 0)
          ghost_dof_forces.push_back({live_cell_owned_dofs.size(), dof});
        live_cell_owned_dofs.push_back(owned);
      }
    }
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const int local = map.LID(static_cast<TrilinosWrappers::types::int_type>(dofs[i]));
      missing = missing || local < 0;
      cell_local_dofs[std::size_t(cell->active_cell_index()) * n_dofs + i] = std::max(local, 0);
    }
  }
  throw_if_any(missing, "far field: a cell's dof is not in the ghosted vector", comm);

  owned_dof_force_begin.assign(std::size_t(owned_map.NumMyElements()) + 1, 0);
  for (const int l : live_cell_owned_dofs)
    if (l >= 0)
      ++owned_dof_force_begin[l + 1];
  for (std::size_t l = 1; l < owned_dof_force_begin.size(); ++l)
    owned_dof_force_begin[l] += owned_dof_force_begin[l - 1];
  owned_dof_forces.resize(owned_dof_force_begin.back());
  std::vector<std::size_t> next(owned_dof_force_begin.begin(), owned_dof_force_begin.end() - 1);
  for (std::size_t entry = 0; entry < live_cell_owned_dofs.size(); ++entry)
    if (const int l = live_cell_owned_dofs[entry]; l >= 0)
      owned_dof_forces[next[l]++] = entry;
  index_cell_shapes();
}

bool FarFieldSolver::Data::is_quiet(const std::vector<double>& u_local, const double size,
                                    const std::size_t first_point) const
{
  const double quiet = quiet_displacement_over_size * size;
  for (const double u : u_local)
    if (!(std::abs(u) <= quiet)) // a NaN is not quiet: the material update reports it
      return false;
  for (std::size_t q = first_point; q < first_point + n_q_points; ++q)
    if (committed_states[q].failure != materials::intact ||
        committed_states[q].plastic.equivalent_plastic_strain != 0.0)
      return false;
  return true;
}

void FarFieldSolver::Data::commit_states()
{
  std::swap(committed_states, trial_states);
  unsigned long long n_failed = 0;
  const bool carries_matrix_failure = prm.failure_proximity == FailureProximity::total_failure;
  // The states come from a pass over live_cells (the integrators commit after one).
  const long n_live = static_cast<long>(live_cells.size());
#pragma omp parallel for schedule(static) reduction(+ : n_failed)
  for (long c = 0; c < n_live; ++c)
  {
    const std::size_t first = std::size_t(live_cells[c]->active_cell_index()) * n_q_points;
    for (unsigned int q = 0; q < n_q_points; ++q)
    {
      const std::uint8_t failure = committed_states[first + q].failure;
      n_failed += (carries_matrix_failure
                     ? (failure & materials::total_failure) == materials::total_failure
                     : failure != materials::intact)
                    ? 1
                    : 0;
    }
  }
  n_failed = Utilities::MPI::sum(n_failed, comm);
  // Loud on the first failure and whenever the count has doubled since the last warning.
  const bool warn = n_failed > 0 && (n_failed_points == 0 || n_failed >= 2 * last_warned_failures);
  if (warn)
    last_warned_failures = n_failed;
  if (warn && Utilities::MPI::this_mpi_process(comm) == 0)
    std::cerr << "\n*** WARNING (vulnus FE): " << n_failed
              << " finite element quadrature points have FAILED"
              << (carries_matrix_failure ? " totally" : "") << " at t = " << time
              << " s. Failure has reached the FE far field: the MPM zone is too small for "
                 "this scene. ***\n"
              << std::endl;
  n_failed_points = n_failed;
}

void FarFieldSolver::Data::assemble_external_forces(const double t, Vector* condensed)
{
  external_force_raw = 0.0;
  bool any_traction = false;
  for (const FaceParameters& face : prm.faces)
    any_traction |= face.condition == FaceParameters::Condition::traction;
  if (any_traction)
  {
    FEFaceValues<3> fe_face_values(mapping, fe, face_quadrature, update_values | update_JxW_values);
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n_dofs);
    dealii::Vector<double> f_local(n_dofs);
    std::vector<double> f_values(n_dofs);
    for (const auto& cell : dof_handler.active_cell_iterators())
      if (owns_live(cell))
        for (const unsigned int f : cell->face_indices())
        {
          if (!cell->face(f)->at_boundary() || cell->face(f)->boundary_id() >= n_slab_faces)
            continue;
          const FaceParameters& face = prm.faces[cell->face(f)->boundary_id()];
          if (face.condition != FaceParameters::Condition::traction)
            continue;
          const double g = face.profile.value(t);
          fe_face_values.reinit(cell, f);
          cell->get_dof_indices(dofs);
          f_local = 0.0;
          for (unsigned int q = 0; q < fe_face_values.n_quadrature_points; ++q)
            for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              f_local(i) += g * face.value[c] * fe_face_values.shape_value_component(i, q, c) *
                            fe_face_values.JxW(q);
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            f_values[i] = f_local(i);
          external_force_raw.add(dofs, f_values);
          if (condensed != nullptr)
            hanging_constraints.distribute_local_to_global(f_local, dofs, *condensed);
        }
  }
  external_force_raw.compress(VectorOperation::add);
  if (condensed != nullptr)
    condensed->compress(VectorOperation::add);
}

double FarFieldSolver::Data::external_power() const
{
  double power = 0.0;
  // Local positions follow the owned dofs' ascending order: the sum owned_dofs would make.
  const double* v = velocity.trilinos_vector()[0];
  const double* f = external_force_raw.trilinos_vector()[0];
  for (std::size_t l = 0; l < velocity.locally_owned_size(); ++l)
    power += v[l] * f[l];
  for (const DirichletDof& d : dirichlet_dofs)
    power +=
        velocity(d.dof) * (internal_force_raw(d.dof) + lumped_mass(d.dof) * acceleration(d.dof) -
                           external_force_raw(d.dof));
  return Utilities::MPI::sum(power, comm);
}

double FarFieldSolver::Data::kinetic_energy() const
{
  double energy = 0.0;
  if (!is_implicit())
  {
    const double* m = lumped_mass.trilinos_vector()[0];
    const double* v = velocity.trilinos_vector()[0];
    for (std::size_t l = 0; l < velocity.locally_owned_size(); ++l)
      energy += 0.5 * m[l] * v[l] * v[l];
    return Utilities::MPI::sum(energy, comm);
  }
  // Consistent mass: 1/2 int rho0 |v_h|^2 dV, evaluated at the quadrature points.
  Vector v(ghosted);
  v = velocity;
  FEValues<3> fe_values(mapping, fe, mass_quadrature, update_values | update_JxW_values);
  const unsigned int n_dofs = fe.n_dofs_per_cell();
  std::vector<types::global_dof_index> dofs(n_dofs);
  for (const auto& cell : dof_handler.active_cell_iterators())
    if (owns_live(cell))
    {
      fe_values.reinit(cell);
      cell->get_dof_indices(dofs);
      for (unsigned int q = 0; q < mass_quadrature.size(); ++q)
      {
        Tensor<1, 3> vq;
        for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int c = fe.system_to_component_index(i).first;
          vq[c] += v(dofs[i]) * fe_values.shape_value_component(i, q, c);
        }
        energy += 0.5 * prm.density * (vq * vq) * fe_values.JxW(q);
      }
    }
  return Utilities::MPI::sum(energy, comm);
}
} // namespace vulnus::fem
