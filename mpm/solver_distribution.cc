// The solver's side of a distributed run (several MPI ranks, one slab of the grid each):
// handing points to the rank owning their slab, summing node data with the neighbouring
// slabs after each particle-to-grid pass, moving the cuts with the points, and the
// reductions of diagnostics, contact results and errors over all ranks.
#include "mpm/solver.h"

#include "mpm/axisymmetry.h"

#include "mpm/body_builder.h"
#include "mpm/point_transfer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vulnus::mpm
{
namespace
{
/// Cell layer of x along `axis`, points outside the grid counted to the end layers; -1 for
/// NaN.
long layer_along(const Grid& grid, const Vector3& x, const int axis)
{
  const double layer = std::clamp(std::floor((x[axis] - grid.origin()[axis]) * grid.inverse_cell_size()),
                                  0.0, double(grid.cells()[axis] - 1));
  return std::isfinite(layer) ? static_cast<long>(layer) : -1;
}

/// Points per cell layer along `axis`.
std::vector<std::uint64_t> layer_histogram(const Particles& particles, const Grid& grid,
                                           const int axis)
{
  std::vector<std::uint64_t> counts(grid.cells()[axis], 0);
  for (const Vector3& x : particles.position)
    if (const long layer = layer_along(grid, x, axis); layer >= 0)
      ++counts[layer];
  return counts;
}
} // namespace

void Solver::plan_slabs()
{
  partition = SlabPartition(0);
  if (!ranks.distributed())
    return;
  // Every rank visits every point position of the scene (nothing stored), so the histograms
  // agree without communication.
  std::vector<std::vector<std::uint64_t>> counts;
  for (int a = 0; a < 3; ++a)
    counts.emplace_back(grid.cells()[a], 0);
  visit_body_points(parameters, grid, [&](const Vector3& x) {
    for (int a = 0; a < 3; ++a)
      if (const long layer = layer_along(grid, x, a); layer >= 0)
        ++counts[a][layer];
  });
  const int axis = choose_slab_axis(counts);
  partition = SlabPartition::balanced(axis, counts[axis], ranks.size());
  // Contact sums count a node shared by two slabs once: on the lower of the two ranks.
  grid_settings.owns_node = [this](const std::int64_t key)
  { return !node_shared_with_lower_rank[grid.slot(key)]; };
}

void Solver::rebalance_slabs()
{
  if (!ranks.distributed())
    return;
  std::vector<std::uint64_t> counts = layer_histogram(particles, grid, partition.axis());
  ranks.sum(counts.data(), static_cast<int>(counts.size()));
  partition = SlabPartition::balanced(partition.axis(), counts, ranks.size());
  migrate_points(true);
}

void Solver::migrate_points(const bool to_any_rank)
{
  if (!ranks.distributed())
    return;
  const int me = ranks.rank();
  // Destination of each leaving point (-1: it stays). A step moves a point by less than a
  // cell (CFL < 1) and slabs are several cells thick, so between re-cuts only the neighbours
  // receive points.
  std::vector<int> destination(particles.size(), -1);
  std::vector<char> stays(particles.size(), 1);
  std::size_t n_leaving = 0;
  RunFailure problem;
  for (std::size_t p = 0; p < particles.size(); ++p)
  {
    const int owner = partition.rank_of_position(grid, particles.position[p]);
    if (owner == me)
      continue;
    destination[p] = owner;
    stays[p] = 0;
    ++n_leaving;
    if (!to_any_rank && std::abs(owner - me) > 1 && problem.empty())
      problem = {"point moved across a whole slab in one step at step " +
                   std::to_string(n_steps) + ", " + describe_point(p),
                 "an unstable step, or a bullet speed far beyond the time step's wave speed",
                 "a smaller {cfl}"};
  }
  problem = ranks.first_failure(problem);
  if (!problem.empty())
    throw BlowUp(problem);

  std::vector<int> partners;
  if (to_any_rank)
    for (int r = 0; r < ranks.size(); ++r)
      partners.push_back(r);
  else
    for (const int r : {me - 1, me + 1})
      if (r >= 0 && r < ranks.size())
        partners.push_back(r);
  std::vector<Particles> leaving;
  if (n_leaving > 0)
    leaving = split_by_destination(particles, destination, ranks.size());
  std::vector<std::vector<char>> outgoing(partners.size());
  for (std::size_t i = 0; i < partners.size(); ++i)
    if (n_leaving > 0 && partners[i] != me)
      outgoing[i] = to_bytes(leaving[partners[i]]);
  const std::vector<std::vector<char>> incoming_bytes =
    to_any_rank ? ranks.exchange_with_all(outgoing) : ranks.exchange_with(partners, outgoing);
  std::vector<Particles> incoming;
  for (std::size_t i = 0; i < partners.size(); ++i)
    if (partners[i] != me && !incoming_bytes[i].empty())
      incoming.push_back(from_bytes(incoming_bytes[i].data(), incoming_bytes[i].size()));
  if (n_leaving > 0 || !incoming.empty())
    exchange_in_place(particles, stays, incoming);
}

namespace
{
/// Adds the partner ranks' entries (n_bodies per node, any type with +=) of the nodes both
/// touch to this rank's; marks the nodes shared with a lower rank.
template <class Entry>
void sum_entries_with_neighbours(const RankGroup& ranks, const SlabPartition& partition,
                                 const Grid& grid, const TransferSettings& transfer,
                                 const std::size_t n_bodies, std::vector<Entry>& entries,
                                 std::vector<char>& node_shared_with_lower_rank)
{
  const int me = ranks.rank();
  const int axis = partition.axis();
  const bool linear = transfer.shape == ShapeFunction::linear;
  const int below = linear ? 0 : 1, above = linear ? 1 : 2;
  const std::size_t record = sizeof(std::int64_t) + n_bodies * sizeof(Entry);
  std::vector<int> partners;
  for (const int r : {me - 1, me + 1})
    if (r >= 0 && r < ranks.size())
      partners.push_back(r);
  std::vector<std::pair<int, int>> reach; // node layers each partner's points touch
  for (const int r : partners)
    reach.push_back(partition.touched_node_layers(r, below, above));
  std::vector<std::vector<char>> outgoing(partners.size());
  for (std::size_t s = 0; s < grid.n_active(); ++s)
  {
    const std::int64_t key = grid.active_keys()[s];
    const int layer = grid.node_ijk(key)[axis];
    for (std::size_t i = 0; i < partners.size(); ++i)
    {
      if (layer < reach[i].first || layer > reach[i].second)
        continue;
      std::vector<char>& out = outgoing[i];
      const std::size_t offset = out.size();
      out.resize(offset + record);
      std::memcpy(out.data() + offset, &key, sizeof(key));
      std::memcpy(out.data() + offset + sizeof(key), &entries[s * n_bodies],
                  n_bodies * sizeof(Entry));
    }
  }
  const std::vector<std::vector<char>> incoming = ranks.exchange_with(partners, outgoing);
  node_shared_with_lower_rank.assign(grid.n_active(), 0);
  for (std::size_t i = 0; i < partners.size(); ++i)
    for (std::size_t offset = 0; offset + record <= incoming[i].size(); offset += record)
    {
      const std::vector<char>& message = incoming[i];
      std::int64_t key = 0;
      std::memcpy(&key, message.data() + offset, sizeof(key));
      const std::int32_t slot = grid.slot(key);
      if (slot < 0)
        continue; // no point of this rank touches it
      if (partners[i] < me)
        node_shared_with_lower_rank[slot] = 1;
      for (std::size_t b = 0; b < n_bodies; ++b)
      {
        Entry other;
        std::memcpy(static_cast<void*>(&other),
                    message.data() + offset + sizeof(key) + b * sizeof(Entry), sizeof(Entry));
        entries[slot * n_bodies + b] += other;
      }
    }
}
} // namespace

void Solver::sum_node_data_with_neighbours()
{
  if (ranks.distributed())
    sum_entries_with_neighbours(ranks, partition, grid, transfer, fields.n_bodies, fields.data,
                                node_shared_with_lower_rank);
}

void Solver::sum_projected_momenta_with_neighbours()
{
  if (ranks.distributed())
    sum_entries_with_neighbours(ranks, partition, grid, transfer, fields.n_bodies,
                                fields.projected_momentum, node_shared_with_lower_rank);
}

void Solver::reduce_contact_result()
{
  if (!ranks.distributed())
    return;
  const std::size_t n_bodies = grid_result.contact_force.size();
  std::vector<double> sums;
  for (const Vector3& f : grid_result.contact_force)
    sums.insert(sums.end(), {f[0], f[1], f[2]});
  for (const Vector3& m : grid_result.contact_moment)
    sums.insert(sums.end(), {m[0], m[1], m[2]});
  sums.push_back(grid_result.contact_dissipation);
  sums.push_back(double(grid_result.n_contact_nodes));
  ranks.sum(sums.data(), static_cast<int>(sums.size()));
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    grid_result.contact_force[b] = Vector3(sums[3 * b], sums[3 * b + 1], sums[3 * b + 2]);
    const std::size_t m = 3 * (n_bodies + b);
    grid_result.contact_moment[b] = Vector3(sums[m], sums[m + 1], sums[m + 2]);
  }
  grid_result.contact_dissipation = sums[6 * n_bodies];
  grid_result.n_contact_nodes = static_cast<std::size_t>(sums[6 * n_bodies + 1]);
  if (std::find(grid_settings.body_is_rigid.begin(), grid_settings.body_is_rigid.end(), 1) !=
      grid_settings.body_is_rigid.end())
    ranks.max(grid_result.peak_node_force.data(), static_cast<int>(n_bodies));
}

SceneDiagnostics Solver::diagnostics() const
{
  SceneDiagnostics d = compute_diagnostics(particles, flight_axis, parameters.gravity);
  if (parameters.axisymmetric) // one rank (Solver's constructor)
    revolve(d);
  if (!ranks.distributed())
    return d;
  // Sums: energies and momentum, then per body mass, first moments, momentum and energies.
  std::vector<double> sums = {d.kinetic_energy, d.strain_energy, d.potential_energy,
                              d.dissipated_energy, d.momentum[0], d.momentum[1], d.momentum[2]};
  std::vector<double> extremes;
  for (const BodySummary& b : d.bodies)
  {
    const Vector3 moment = b.mass * b.centroid, momentum = b.mass * b.velocity;
    sums.insert(sums.end(), {b.mass, moment[0], moment[1], moment[2], momentum[0], momentum[1],
                             momentum[2], b.kinetic_energy, b.strain_energy, b.dissipated_energy});
    extremes.insert(extremes.end(), {-b.min_along, b.max_along});
  }
  ranks.sum(sums.data(), static_cast<int>(sums.size()));
  ranks.max(extremes.data(), static_cast<int>(extremes.size()));
  std::uint64_t counts[4];
  for (int k = 0; k < 4; ++k)
    counts[k] = d.failure_counts[k];
  ranks.sum(counts, 4);
  d.kinetic_energy = sums[0];
  d.strain_energy = sums[1];
  d.potential_energy = sums[2];
  d.dissipated_energy = sums[3];
  d.momentum = Vector3(sums[4], sums[5], sums[6]);
  for (int k = 0; k < 4; ++k)
    d.failure_counts[k] = counts[k];
  for (std::size_t i = 0; i < d.bodies.size(); ++i)
  {
    const double* s = &sums[7 + 10 * i];
    BodySummary& b = d.bodies[i];
    b.mass = s[0];
    b.centroid = b.mass > 0 ? Vector3(Vector3(s[1], s[2], s[3]) / b.mass) : Vector3(Vector3::Zero());
    b.velocity = b.mass > 0 ? Vector3(Vector3(s[4], s[5], s[6]) / b.mass) : Vector3(Vector3::Zero());
    b.kinetic_energy = s[7];
    b.strain_energy = s[8];
    b.dissipated_energy = s[9];
    b.min_along = -extremes[2 * i];
    b.max_along = extremes[2 * i + 1];
  }
  return d;
}

Particles Solver::gather_points() const
{
  if (!ranks.distributed())
    return particles;
  const std::vector<std::vector<char>> messages = ranks.gather_to_root(to_bytes(particles));
  std::vector<Particles> parts;
  for (const std::vector<char>& message : messages)
    parts.push_back(from_bytes(message.data(), message.size()));
  Particles none;
  none.body_begin.assign(particles.n_bodies() + 1, 0);
  return merge_points(none, {}, parts);
}

std::size_t Solver::n_points_all_ranks() const
{
  return ranks.sum(static_cast<std::uint64_t>(particles.size()));
}

std::size_t Solver::active_nodes_all_ranks() const
{
  return ranks.sum(static_cast<std::uint64_t>(n_active_last_step));
}
} // namespace vulnus::mpm
