// Binary save and restore of the far field's evolving state on this rank (the mesh, dofs and
// partition are rebuilt from the deck by setup(), so a restart needs the same rank count):
// the solution vectors, the raw force vectors the diagnostics read, the quadrature-point
// histories and cell fields, the boundary impulses and the running energies.
#include "fem/far_field_data.h"
#include "mpm/binary_io.h"

namespace vulnus::fem
{
using namespace dealii;
namespace binary = mpm::binary;

namespace
{
constexpr char tag[8] = {'V', 'U', 'L', 'F', 'E', 'C', 'K', '3'};

/// The running scalars, in checkpoint order, for save (put) and restore (get) alike.
template <class Data, class Visit>
void visit_scalars(Data& d, Visit visit)
{
  visit(d.last_sums);
  visit(d.time);
  visit(d.step);
  visit(d.external_work);
  visit(d.external_work_in);
  visit(d.last_power);
  visit(d.dissipated_energy);
  visit(d.n_failed_points);
  visit(d.last_warned_failures);
}

void put_tensors(std::ostream& out, const std::vector<Tensor<1, 3>>& tensors)
{
  std::vector<double> flat;
  for (const Tensor<1, 3>& t : tensors)
    flat.insert(flat.end(), {t[0], t[1], t[2]});
  binary::put_vector(out, flat);
}

void get_tensors(std::istream& in, std::vector<Tensor<1, 3>>& tensors, const std::size_t expected)
{
  std::vector<double> flat;
  binary::get_vector(in, flat);
  if (flat.size() != 3 * expected)
    throw std::runtime_error("FE checkpoint is inconsistent (a node list has another length)");
  tensors.resize(expected);
  for (std::size_t k = 0; k < expected; ++k)
    tensors[k] = Tensor<1, 3>({flat[3 * k], flat[3 * k + 1], flat[3 * k + 2]});
}
} // namespace

void FarFieldSolver::save(std::ostream& out) const
{
  const Data& d = *data;
  forget_implicit_preconditioner(*data);
  out.write(tag, sizeof(tag));
  binary::put(out, static_cast<std::uint64_t>(d.owned_dofs.n_elements()));
  for (const Data::Vector* v : {&d.displacement, &d.velocity, &d.acceleration,
                                &d.internal_force_raw, &d.external_force_raw,
                                &d.inertia_coupling_raw})
  {
    std::vector<double> values;
    values.reserve(d.owned_dofs.n_elements());
    for (const auto i : d.owned_dofs)
      values.push_back((*v)(i));
    binary::put_vector(out, values);
  }
  binary::put_vector(out, d.committed_states);
  std::vector<double> stresses;
  for (const Tensor<2, 3>& s : d.cell_stress)
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        stresses.push_back(s[a][b]);
  binary::put_vector(out, stresses);
  binary::put_vector(out, d.cell_failure);
  binary::put_vector(out, d.cell_wave_speed);
  binary::put_vector(out, d.cell_failure_proximity);
  binary::put(out, d.n_converted_cells);
  put_tensors(out, d.interface_velocity_targets);
  put_tensors(out, d.boundary_now.interface);
  put_tensors(out, d.interface_impulse_last_step);
  put_tensors(out, std::vector<Tensor<1, 3>>(d.boundary_now.supports.begin(), d.boundary_now.supports.end()));
  put_tensors(out, std::vector<Tensor<1, 3>>(d.support_impulse.begin(), d.support_impulse.end()));
  visit_scalars(d, [&out](const auto& value) { binary::put(out, value); });
  out.write(tag, sizeof(tag));
  if (!out)
    throw std::runtime_error("FE checkpoint could not be written");
}

void FarFieldSolver::restore(std::istream& in)
{
  Data& d = *data;
  binary::expect_tag(in, tag, "not a vulnus FE checkpoint (bad header)");
  std::uint64_t n_owned = 0;
  binary::get(in, n_owned);
  if (n_owned != d.owned_dofs.n_elements())
    throw std::runtime_error("FE checkpoint holds " + std::to_string(n_owned) +
                             " dofs on this rank, the mesh " +
                             std::to_string(d.owned_dofs.n_elements()) + ": it belongs to another scene");
  for (Data::Vector* v : {&d.displacement, &d.velocity, &d.acceleration, &d.internal_force_raw,
                          &d.external_force_raw, &d.inertia_coupling_raw})
  {
    std::vector<double> values;
    binary::get_vector(in, values);
    if (values.size() != n_owned)
      throw std::runtime_error("FE checkpoint is inconsistent (vector lengths)");
    std::size_t k = 0;
    for (const auto i : d.owned_dofs)
      (*v)(i) = values[k++];
    v->compress(VectorOperation::insert);
  }
  std::vector<materials::PointState> states;
  binary::get_vector(in, states);
  std::vector<double> stresses;
  binary::get_vector(in, stresses);
  std::vector<unsigned char> failure;
  binary::get_vector(in, failure);
  std::vector<double> wave_speed;
  binary::get_vector(in, wave_speed);
  std::vector<double> proximity;
  binary::get_vector(in, proximity);
  unsigned long long n_converted = 0;
  binary::get(in, n_converted);
  if (states.size() != d.committed_states.size() || stresses.size() != 9 * d.cell_stress.size() ||
      failure.size() != d.cell_failure.size() || wave_speed.size() != d.cell_wave_speed.size() ||
      proximity.size() != d.cell_failure_proximity.size())
    throw std::runtime_error("FE checkpoint is inconsistent (cell data lengths)");
  if (n_converted != d.n_converted_cells)
    throw std::runtime_error("FE checkpoint was written with " + std::to_string(n_converted) +
                             " far-field cells converted, this far field has " +
                             std::to_string(d.n_converted_cells) + ": convert the same cells first");
  d.cell_failure_proximity = proximity;
  d.committed_states = states;
  d.trial_states = states;
  for (std::size_t c = 0; c < d.cell_stress.size(); ++c)
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        d.cell_stress[c][a][b] = stresses[9 * c + 3 * a + b];
  d.cell_failure = failure;
  d.cell_wave_speed = wave_speed;
  get_tensors(in, d.interface_velocity_targets, d.interface_nodes.size());
  get_tensors(in, d.boundary_now.interface, d.interface_nodes.size());
  get_tensors(in, d.interface_impulse_last_step, d.interface_nodes.size());
  std::vector<Tensor<1, 3>> faces;
  get_tensors(in, faces, n_slab_faces + 1);
  std::copy(faces.begin(), faces.end(), d.boundary_now.supports.begin());
  d.reset_booked_dirichlet_velocities(); // they were booked up to the saved state
  get_tensors(in, faces, n_slab_faces + 1);
  std::copy(faces.begin(), faces.end(), d.support_impulse.begin());
  visit_scalars(d, [&in](auto& value) { binary::get(in, value); });
  binary::expect_tag(in, tag, "FE checkpoint is incomplete (no trailer)");
}
} // namespace vulnus::fem
