// Each body's points split into fixed shares (one per thread) for the scatters to the grid.
// The node marking records which share touches each node; a node only one share touches is
// written straight into the grid fields by that share's thread, and only the few nodes on the
// seams between shares ("contested") go through small per-share buffers that are summed
// afterwards. Shares, not threads, own nodes, so the result is right whatever team size OpenMP
// provides; sorted points keep the seams thin.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"

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

/// Sizes the per-share buffers of the contested entries (n_contested x n_bodies each); each
/// share's thread clears its own (clear_contested) before scattering.
template <class Entry>
void size_contested(const Grid& grid, const std::size_t n_bodies,
                    std::vector<std::vector<Entry>>& per_share)
{
  per_share.resize(grid.n_point_shares());
  for (std::vector<Entry>& buffer : per_share)
    buffer.resize(grid.n_contested() * n_bodies);
}

/// Sets every entry to zero (Eigen vectors have no zeroing default constructor).
template <class Entry>
void clear_contested(std::vector<Entry>& buffer, const Entry& zero)
{
  std::fill(buffer.begin(), buffer.end(), zero);
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
