// The implicit step's interface stiffness: the Schur complement of the Newton matrix on the
// interface dofs, column by column. A unit displacement of one interface dof (the others held,
// the rest of the body free) is answered by the forces the interface nodes need; the hybrid
// coupling builds from it the window's effective interface mass (docs/far_field.md, section 1).
// The held matrix is factorized once (MUMPS through Amesos) and every probe is a pair of
// triangular solves, or, for far fields too large to factorize, a CG solve per probe.
#include "fem/far_field_data.h"
#include "fem/cell_stiffness.h"
#include "fem/ordered_cell_loop.h"
#include "fem/tensor_conversion.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <stdexcept>

namespace vulnus::fem
{
using namespace dealii;

struct InterfaceStiffnessData
{
  TrilinosWrappers::SparseMatrix matrix; ///< Newton matrix, interface and supports held
  TrilinosWrappers::PreconditionAMG preconditioner; ///< iterative probing
  SolverControl direct_control;                     ///< the direct solver keeps a reference
  std::unique_ptr<TrilinosWrappers::SolverDirect> direct; ///< factorized once, every probe
  /// Cells holding an interface dof: their dofs and full (unconstrained) cell matrices.
  std::vector<std::vector<types::global_dof_index>> cell_dofs;
  std::vector<FullMatrix<double>> cell_matrices;
};

namespace
{
/// Largest far field (global dofs) whose interface stiffness `automatic` factorizes. The
/// coarse decks' 25,872 dofs factorize in 1.3 s; the bound keeps the factor's memory (its fill
/// grows faster than the dofs in 3D) to far fields a few times larger, where it was not measured.
constexpr types::global_dof_index direct_interface_stiffness_dofs = 150000;

/// Flags (ghosted, 1.0) the interface dofs every rank's cells can see.
FarFieldSolver::Data::Vector interface_dof_flags(const FarFieldSolver::Data& d)
{
  FarFieldSolver::Data::Vector owned(d.owned_dofs, d.comm);
  for (const DirichletDof& dirichlet : d.dirichlet_dofs)
    if (dirichlet.source == DirichletSource::interface)
      owned(dirichlet.dof) = 1.0;
  owned.compress(VectorOperation::insert);
  FarFieldSolver::Data::Vector ghosted(d.owned_dofs, d.relevant_dofs, d.comm);
  ghosted = owned;
  return ghosted;
}
} // namespace

void FarFieldSolver::prepare_interface_stiffness(const double dt)
{
  Data& d = *data;
  if (!d.is_implicit())
    throw std::logic_error("interface stiffness: the far field is not implicit");
  const double beta = implicit_beta(d.prm), alpha_m = implicit_alpha_m(d.prm),
               alpha_f = implicit_alpha_f(d.prm);
  const double mass_factor = (1.0 - alpha_m) / (beta * dt * dt);
  const double stiffness_factor = 1.0 - alpha_f;

  auto s = std::make_shared<InterfaceStiffnessData>();
  TrilinosWrappers::SparsityPattern sparsity(d.owned_dofs, d.owned_dofs, d.relevant_dofs, d.comm);
  DoFTools::make_sparsity_pattern(d.dof_handler, sparsity, d.increment_constraints, false,
                                  Utilities::MPI::this_mpi_process(d.comm));
  sparsity.compress();
  s->matrix.reinit(sparsity);

  const Data::Vector on_interface = interface_dof_flags(d);
  d.ghosted = d.displacement;
  if (d.cell_local_dofs.empty())
    d.index_cell_dofs(d.ghosted);
  const unsigned int n_dofs = d.fe.n_dofs_per_cell();
  const std::vector<unsigned int> component = dof_components(d.fe);
  const double* u_values = d.ghosted.trilinos_vector()[0];
  const double* flags = on_interface.trilinos_vector()[0];
  struct Worker
  {
    explicit Worker(const Data& d)
      : fe_values(d.mapping, d.fe, d.quadrature,
                  update_values | update_gradients | update_JxW_values),
        values(d.fe.n_dofs_per_cell()), u_local(d.fe.n_dofs_per_cell()), states(d.n_q_points)
    {
    }
    FEValues<3> fe_values;
    CellStiffness law;
    std::vector<double> values, u_local;
    std::vector<materials::PointState> states;
  };
  struct Cell
  {
    std::vector<types::global_dof_index> dofs;
    FullMatrix<double> matrix;
    bool touches_interface = false;
  };
  // The cells' matrices on the threads, added in cell order.
  ordered_cell_loop<Cell>(
    static_cast<long>(d.live_cells.size()), 32, [&]() { return std::make_unique<Worker>(d); },
    [&](Worker& w, const long c, Cell& out)
    {
      const auto& cell = d.live_cells[static_cast<std::size_t>(c)];
      const std::size_t k = cell->active_cell_index();
      w.fe_values.reinit(cell);
      out.dofs.resize(n_dofs);
      cell->get_dof_indices(out.dofs);
      const int* local = &d.cell_local_dofs[k * n_dofs];
      out.touches_interface = false;
      for (unsigned int i = 0; i < n_dofs; ++i)
      {
        w.u_local[i] = u_values[local[i]];
        out.touches_interface = out.touches_interface || flags[local[i]] != 0.0;
      }
      const std::size_t first = k * d.n_q_points;
      std::copy_n(&d.committed_states[first], d.n_q_points, w.states.begin());
      w.law.evaluate(w.fe_values, component, w.u_local, *d.material, &d.fiber_directions[first],
                     w.states.data(), d.prm.volume_averaging, dt);
      out.matrix.reinit(n_dofs, n_dofs);
      for (unsigned int q = 0; q < d.n_q_points; ++q)
      {
        const double rho_JxW = d.prm.density * w.fe_values.JxW(q);
        for (unsigned int i = 0; i < n_dofs; ++i)
          w.values[i] = w.fe_values.shape_value_component(i, q, component[i]);
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j < n_dofs; ++j)
            if (component[i] == component[j])
              out.matrix(i, j) += mass_factor * rho_JxW * w.values[i] * w.values[j];
      }
      for (unsigned int i = 0; i < n_dofs; ++i)
        for (unsigned int j = 0; j < n_dofs; ++j)
          out.matrix(i, j) += stiffness_factor * w.law.stiffness(i, j);
    },
    [&](long, Cell& cell)
    {
      if (cell.touches_interface)
      {
        s->cell_dofs.push_back(cell.dofs);
        s->cell_matrices.push_back(cell.matrix);
      }
      d.increment_constraints.distribute_local_to_global(cell.matrix, cell.dofs, s->matrix);
    });
  for (const auto dof : d.dead_dofs)
    s->matrix.add(dof, dof, mass_factor * d.dead_dof_mass);
  s->matrix.compress(VectorOperation::add);

  const bool direct =
    d.prm.interface_stiffness_solver == InterfaceStiffnessSolver::direct ||
    (d.prm.interface_stiffness_solver == InterfaceStiffnessSolver::automatic &&
     d.dof_handler.n_dofs() <= direct_interface_stiffness_dofs);
  if (direct)
  {
    s->direct = std::make_unique<TrilinosWrappers::SolverDirect>(
      s->direct_control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
    s->direct->initialize(s->matrix);
    d.interface_stiffness = s;
    return;
  }
  TrilinosWrappers::PreconditionAMG::AdditionalData amg;
  amg.elliptic = true;
  amg.higher_order_elements = d.prm.degree > 1;
  amg.smoother_sweeps = 2;
  amg.aggregation_threshold = 0.02;
  std::vector<std::vector<bool>> constant_modes;
  DoFTools::extract_constant_modes(d.dof_handler, ComponentMask(), constant_modes);
  amg.constant_modes = constant_modes;
  s->preconditioner.initialize(s->matrix, amg);
  d.interface_stiffness = s;
}

std::vector<Tensor<1, 3>> FarFieldSolver::interface_stiffness_response(
  const std::vector<types::global_dof_index>& dofs) const
{
  Data& d = *data;
  if (!d.interface_stiffness)
    throw std::logic_error("interface stiffness: prepare_interface_stiffness was not called");
  const InterfaceStiffnessData& s = *d.interface_stiffness;
  // The unit displacements of `dofs` (held), the rest of the body's answer, and the forces on
  // the interface rows.
  Data::Vector unit(d.owned_dofs, d.comm);
  for (const types::global_dof_index dof : dofs)
    if (d.owned_dofs.is_element(dof))
      unit(dof) = 1.0;
  unit.compress(VectorOperation::insert);
  Data::Vector unit_ghosted(d.owned_dofs, d.relevant_dofs, d.comm);
  unit_ghosted = unit;

  const unsigned int n_dofs = d.fe.n_dofs_per_cell();
  Vector<double> local(n_dofs), product(n_dofs);
  Data::Vector rhs(d.owned_dofs, d.comm);
  for (std::size_t c = 0; c < s.cell_dofs.size(); ++c)
  {
    bool holds = false;
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      local(i) = unit_ghosted(s.cell_dofs[c][i]);
      holds = holds || local(i) != 0.0;
    }
    if (!holds)
      continue;
    s.cell_matrices[c].vmult(product, local);
    product *= -1.0;
    d.increment_constraints.distribute_local_to_global(product, s.cell_dofs[c], rhs);
  }
  rhs.compress(VectorOperation::add);

  Data::Vector answer(d.owned_dofs, d.comm);
  const double norm = rhs.l2_norm();
  if (norm > 0.0 && s.direct)
    s.direct->solve(answer, rhs);
  else if (norm > 0.0)
  {
    // The matrix only steers the balance's chord iteration, which closes each window to its
    // own tolerance, and probing already leaves 0.4 % out: 1e-6 is ample (1e-12 cost 1.7
    // times as much on the paper deck and gave the same failed points).
    SolverControl control(d.prm.max_linear_iterations, 1e-6 * norm);
    TrilinosWrappers::SolverCG solver(control);
    solver.solve(s.matrix, answer, rhs, s.preconditioner);
  }
  d.increment_constraints.distribute(answer);
  answer += unit;
  Data::Vector answer_ghosted(d.owned_dofs, d.relevant_dofs, d.comm);
  answer_ghosted = answer;

  Data::Vector forces(d.owned_dofs, d.comm);
  std::vector<double> add(n_dofs);
  for (std::size_t c = 0; c < s.cell_dofs.size(); ++c)
  {
    for (unsigned int i = 0; i < n_dofs; ++i)
      local(i) = answer_ghosted(s.cell_dofs[c][i]);
    s.cell_matrices[c].vmult(product, local);
    for (unsigned int i = 0; i < n_dofs; ++i)
      add[i] = product(i);
    forces.add(s.cell_dofs[c], add);
  }
  forces.compress(VectorOperation::add);
  std::vector<Tensor<1, 3>> column(d.interface_nodes.size());
  for (std::size_t n = 0; n < d.interface_nodes.size(); ++n)
    for (unsigned int c = 0; c < 3; ++c)
      column[n][c] = forces(d.interface_nodes[n].dofs[c]);
  return column;
}

void FarFieldSolver::release_interface_stiffness() { data->interface_stiffness.reset(); }

double FarFieldSolver::interface_mass_factor(const double dt) const
{
  return implicit_beta(data->prm) * dt * dt / (1.0 - implicit_alpha_f(data->prm));
}
} // namespace vulnus::fem
