// Binary save and restore of a hybrid run: the MPM zone, the far field, then the coupling's
// own state between steps.
#include "coupling/hybrid_solver.h"
#include "mpm/binary_io.h"

#include <algorithm>

namespace vulnus::coupling
{
namespace binary = mpm::binary;

namespace
{
constexpr char tag[8] = {'V', 'U', 'L', 'H', 'Y', 'B', 'R', '8'};
} // namespace

void HybridSolver::save(std::ostream& out) const
{
  // The zone first: a restart converts the far field's cells of a grown zone before reading it.
  out.write(tag, sizeof(tag));
  binary::put(out, split.hybrid.zone_min);
  binary::put(out, split.hybrid.zone_max);
  mpm_solver->save(out);
  fe_solver->save(out);
  out.write(tag, sizeof(tag));
  binary::put(out, static_cast<std::uint64_t>(keys.size()));
  binary::put(out, window_start);
  binary::put(out, window_end);
  binary::put(out, static_cast<std::uint8_t>(window_open));
  for (const std::vector<mpm::Vector3>* v : {&velocity_start, &velocity_end, &created, &correction})
    binary::put_vector(out, *v);
  binary::put(out, book);
  binary::put(out, last_zone_check);
  binary::put(out, n_cells_beyond_limit);
  binary::put_vector(out, zone_conversions);
  // Balanced windows: the far field's state at the window's start (a checkpoint may fall
  // inside a window), its step's impulses, the interface now and the effective-mass matrix.
  binary::put(out, static_cast<std::uint64_t>(fe_state_at_window_start.size()));
  out.write(fe_state_at_window_start.data(),
            static_cast<std::streamsize>(fe_state_at_window_start.size()));
  binary::put_vector(out, fe_window_impulse);
  binary::put_vector(out, interface_now);
  binary::put(out, balance_window_length);
  binary::put(out, balance_scale);
  binary::put(out, static_cast<std::uint64_t>(balance_matrix.rows()));
  std::vector<std::int64_t> rows, columns;
  std::vector<double> values;
  for (Eigen::Index j = 0; j < balance_matrix.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(balance_matrix, j); it; ++it)
    {
      rows.push_back(it.row());
      columns.push_back(it.col());
      values.push_back(it.value());
    }
  binary::put_vector(out, rows);
  binary::put_vector(out, columns);
  binary::put_vector(out, values);
  binary::put_vector(out, balance_mpm_mass);
  binary::put(out, impulse_left_by_retirement);
  binary::put_vector(out, dashpot_free_velocity);
  binary::put(out, dashpot_ratio);
  binary::put_vector(out, dashpot_mass);
  for (const double v : {mpm_work_at_window_start, fe_work_at_window_start, largest_window_work})
    binary::put(out, v);
  // A following interface: where its nodes were spread when the window opened.
  binary::put_vector(out, grid_keys);
  binary::put_vector(out, spread_begin);
  binary::put_vector(out, spread_node);
  binary::put_vector(out, spread_weight);
  binary::put_vector(out, grid_velocity_start);
  binary::put_vector(out, grid_velocity_end);
  binary::put_vector(out, interface_position);
  binary::put_vector(out, interface_gradient);
  out.write(tag, sizeof(tag));
  if (!out)
    throw std::runtime_error("hybrid checkpoint could not be written");
}

void HybridSolver::restore(std::istream& in)
{
  binary::expect_tag(in, tag, "not a vulnus hybrid checkpoint of this version (bad header)");
  std::array<double, 3> zone_min{}, zone_max{};
  binary::get(in, zone_min);
  binary::get(in, zone_max);
  if (zone_min != split.hybrid.zone_min || zone_max != split.hybrid.zone_max)
  {
    // The run had grown its zone: the far field converts the same cells, its state read below.
    split.hybrid.zone_min = zone_min;
    split.hybrid.zone_max = zone_max;
    for (int d = 0; d < 3; ++d)
    {
      split.mpm.bodies[split.coupled_body].box_min[d] = zone_min[d];
      split.mpm.bodies[split.coupled_body].box_max[d] = zone_max[d];
    }
    fe_solver->convert_cells_inside(zone_min, zone_max);
    match_interface_nodes(comm);
    for (std::vector<mpm::Vector3>* v : {&velocity_start, &velocity_end, &created, &correction})
      v->assign(keys.size(), mpm::Vector3::Zero());
    if (!follows_interface())
      mpm_solver->share_nodes({split.coupled_body, keys, this});
    retire_far_field_if_empty();
  }
  mpm_solver->restore(in);
  fe_solver->restore(in);
  binary::expect_tag(in, tag, "not a vulnus hybrid checkpoint (bad coupling header)");
  std::uint64_t n_keys = 0;
  binary::get(in, n_keys);
  if (n_keys != keys.size())
    throw std::runtime_error("hybrid checkpoint has " + std::to_string(n_keys) +
                             " interface nodes, the scene " + std::to_string(keys.size()));
  binary::get(in, window_start);
  binary::get(in, window_end);
  std::uint8_t open = 0;
  binary::get(in, open);
  window_open = open != 0;
  for (std::vector<mpm::Vector3>* v : {&velocity_start, &velocity_end, &created, &correction})
  {
    binary::get_vector(in, *v);
    if (v->size() != keys.size())
      throw std::runtime_error("hybrid checkpoint is inconsistent (interface vectors)");
  }
  binary::get(in, book);
  binary::get(in, last_zone_check);
  binary::get(in, n_cells_beyond_limit);
  binary::get_vector(in, zone_conversions);
  std::uint64_t state_size = 0;
  binary::get(in, state_size);
  fe_state_at_window_start.resize(state_size);
  in.read(fe_state_at_window_start.data(), static_cast<std::streamsize>(state_size));
  binary::get_vector(in, fe_window_impulse);
  binary::get_vector(in, interface_now);
  binary::get(in, balance_window_length);
  binary::get(in, balance_scale);
  std::uint64_t rows = 0;
  binary::get(in, rows);
  if (!in || rows > 3 * keys.size())
    throw std::runtime_error("hybrid checkpoint is inconsistent (balance matrix)");
  std::vector<std::int64_t> entry_rows, entry_columns;
  std::vector<double> values;
  binary::get_vector(in, entry_rows);
  binary::get_vector(in, entry_columns);
  binary::get_vector(in, values);
  if (!in || entry_rows.size() != values.size() || entry_columns.size() != values.size())
    throw std::runtime_error("hybrid checkpoint is inconsistent (balance matrix)");
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t e = 0; e < values.size(); ++e)
  {
    if (entry_rows[e] < 0 || entry_columns[e] < 0 || std::uint64_t(entry_rows[e]) >= rows ||
        std::uint64_t(entry_columns[e]) >= rows)
      throw std::runtime_error("hybrid checkpoint is inconsistent (balance matrix entry)");
    entries.emplace_back(static_cast<int>(entry_rows[e]), static_cast<int>(entry_columns[e]),
                         values[e]);
  }
  balance_matrix.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(rows));
  balance_matrix.setFromTriplets(entries.begin(), entries.end());
  std::vector<double> masses;
  binary::get_vector(in, masses);
  if (rows > 0 && masses.size() == keys.size())
    factor_balance_matrix(masses);
  binary::get(in, impulse_left_by_retirement);
  binary::get_vector(in, dashpot_free_velocity);
  binary::get(in, dashpot_ratio);
  binary::get_vector(in, dashpot_mass);
  for (double* v : {&mpm_work_at_window_start, &fe_work_at_window_start, &largest_window_work})
    binary::get(in, *v);
  if (dashpot_windows() && rows > 0 && dashpot_mass.size() == keys.size())
  {
    factor_effective_mass(std::vector<double>(keys.size(), 0.0), balance_free_solver);
    factor_dashpot(dashpot_ratio, dashpot_mass);
  }
  binary::get_vector(in, grid_keys);
  binary::get_vector(in, spread_begin);
  binary::get_vector(in, spread_node);
  binary::get_vector(in, spread_weight);
  binary::get_vector(in, grid_velocity_start);
  binary::get_vector(in, grid_velocity_end);
  binary::get_vector(in, interface_position);
  binary::get_vector(in, interface_gradient);
  if (follows_interface())
  {
    if (!in || spread_begin.size() != keys.size() + 1 ||
        spread_node.size() != spread_weight.size() || spread_begin.back() != spread_node.size() ||
        grid_velocity_start.size() != grid_keys.size() ||
        grid_velocity_end.size() != grid_keys.size() ||
        interface_position.size() != keys.size() ||
        std::any_of(spread_node.begin(), spread_node.end(),
                    [&](const std::uint32_t g) { return g >= grid_keys.size(); }))
      throw std::runtime_error("hybrid checkpoint is inconsistent (following interface)");
    spread_interface_masses();
    if (!retired)
      mpm_solver->share_nodes({split.coupled_body, grid_keys, this});
  }
  binary::expect_tag(in, tag, "hybrid checkpoint is incomplete (no trailer)");
}
} // namespace vulnus::coupling
