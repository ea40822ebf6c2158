// Each body's points split into fixed shares (one per thread) for the scatters to the grid.
// The node marking records which share touches each node; a node only one share touches is
// written straight into the grid fields by that share's thread, and only the few nodes on the
// seams between shares ("contested") go through small per-share buffers that are summed
// afterwards. Shares, not threads, own nodes, so the result is right whatever team size OpenMP
// provides; sorted points keep the seams thin.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
struct ShareRange
{
  long begin = 0, end = 0;
};

/// Points [begin, end) of one body cut into n_shares nearly equal consecutive pieces.
inline ShareRange share_of(const long begin, const long end, const int share, const int n_shares)
{
  const long n = end - begin;
  return {begin + n * share / n_shares, begin + n * (share + 1) / n_shares};
}

/// Per-share buffers of the contested nodes, reused across steps.
struct ScatterBuffers
{
  std::vector<std::vector<NodeBodyData>> per_share;
  std::vector<std::vector<Vector3>> momentum_per_share; ///< MUSL re-projection
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

/// Per-share buffers of the contested entries (n_contested x n_bodies each), cleared.
template <class Entry>
void size_and_clear_contested(const Grid& grid, const std::size_t n_bodies,
                              std::vector<std::vector<Entry>>& per_share)
{
  per_share.resize(grid.n_point_shares());
  for (std::vector<Entry>& buffer : per_share)
    buffer.assign(grid.n_contested() * n_bodies, Entry());
}

/// Inside a parallel region, after a barrier: adds every share's contested entries, in share
/// order, into the (zero) grid entries of those nodes.
template <class Entry>
void add_contested(const Grid& grid, const std::size_t n_bodies,
                   const std::vector<std::vector<Entry>>& per_share, Entry* fields)
{
  const long n_contested = static_cast<long>(grid.n_contested());
#pragma omp for schedule(static)
  for (long c = 0; c < n_contested; ++c)
  {
    const std::size_t slot = grid.contested_slots()[c];
    for (std::size_t b = 0; b < n_bodies; ++b)
      for (const std::vector<Entry>& buffer : per_share)
        fields[slot * n_bodies + b] += buffer[c * n_bodies + b];
  }
}
} // namespace vulnus::mpm
