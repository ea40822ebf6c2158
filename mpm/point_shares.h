// Each body's points split into fixed shares (one per thread) for the scatters to the grid.
// The node marking records which share touches each node; a node only one share touches is
// written straight into the grid fields by that share's thread, and only the few nodes on the
// seams between shares ("contested") go through small per-share buffers that are summed
// afterwards. Shares, not threads, own nodes, so the result is right whatever team size OpenMP
// provides; sorted points keep the seams thin.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/particles.h"

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
struct ShareRange
{
  long begin = 0, end = 0;
};

/// Points [begin, end) of one body cut into n_shares consecutive pieces whose sizes differ by
/// at most one, the larger ones first (the split of an OpenMP static schedule).
inline ShareRange share_of(const long begin, const long end, const int share, const int n_shares)
{
  const long n = end - begin, size = n / n_shares, larger = n % n_shares;
  const long first = begin + share * size + std::min<long>(share, larger);
  return {first, first + size + (share < larger ? 1 : 0)};
}

/// Per-share buffers of the contested nodes, reused across steps.
struct ScatterBuffers
{
  std::vector<std::vector<NodeBodyData>> per_share;
  std::vector<std::vector<Vector3>> momentum_per_share; ///< MUSL re-projection
  std::vector<std::vector<SymmetricTensor>> stress_per_share; ///< contact's compression criterion
};

/// The entry a share writes for (node slot, body): the grid field itself, or the share's own
/// buffer when the node is contested.
template <class Entry>
inline Entry& scatter_target(const Grid& grid, const std::int32_t slot, const std::size_t n_bodies,
                             const std::size_t body, Entry* fields, Entry* contested)
{
  const std::int32_t c = grid.contested_index(slot);
  return c < 0 ? fields[slot * n_bodies + body] : contested[c * n_bodies + body];
}

/// Inside a parallel region: calls visit(share, body, range) for every body's points of each
/// share this thread runs (shares t, t + team, ...: any team size covers all shares).
template <class Visit>
void visit_own_shares(const Particles& particles, const int n_shares, Visit&& visit)
{
  const int team = omp_get_num_threads();
  for (int share = omp_get_thread_num(); share < n_shares; share += team)
    for (std::size_t b = 0; b < particles.n_bodies(); ++b)
      visit(share, b, share_of(particles.begin_of(b), particles.end_of(b), share, n_shares));
}

/// Visits every share's points, each share on one thread of a new parallel region.
template <class Visit>
void visit_shares_in_parallel(const Particles& particles, const int n_shares, Visit&& visit)
{
#pragma omp parallel
  visit_own_shares(particles, n_shares, visit);
}

/// Sums per-point contributions into the grid field `fields` (n_active x n_bodies entries,
/// sized by the caller) by the shares of the last node marking: zeroes it and the per-share
/// buffers of the contested nodes, runs scatter(share, body, range, fields, contested) over
/// every share's points (each share on one thread; it adds through scatter_target), then adds the
/// contested buffers in share order. `zero` is the entry's zero (Eigen vectors are not zeroed
/// by their default constructor).
template <class Entry, class Scatter>
void scatter_by_shares(const Grid& grid, const Particles& particles, const Entry& zero,
                       std::vector<Entry>& fields, std::vector<std::vector<Entry>>& per_share,
                       Scatter&& scatter)
{
  const std::size_t n_bodies = particles.n_bodies();
  const int n_shares = grid.n_point_shares();
  per_share.resize(n_shares);
  for (std::vector<Entry>& buffer : per_share)
    buffer.resize(grid.n_contested() * n_bodies);
  const long n_entries = static_cast<long>(fields.size());
  const long n_contested = static_cast<long>(grid.n_contested());
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (long e = 0; e < n_entries; ++e)
      fields[e] = zero;
#pragma omp for schedule(static)
    for (int share = 0; share < n_shares; ++share)
      std::fill(per_share[share].begin(), per_share[share].end(), zero);
    visit_own_shares(particles, n_shares,
                     [&](const int share, const std::size_t b, const ShareRange range)
                     { scatter(share, b, range, fields.data(), per_share[share].data()); });
#pragma omp barrier
#pragma omp for schedule(static)
    for (long c = 0; c < n_contested; ++c)
    {
      const std::size_t slot = grid.contested_slots()[c];
      for (std::size_t b = 0; b < n_bodies; ++b)
        for (const std::vector<Entry>& buffer : per_share)
          fields[slot * n_bodies + b] += buffer[c * n_bodies + b];
    }
  }
}
} // namespace vulnus::mpm
