// Slab decomposition of the background grid for distributed runs: rank r owns the cell layers
// [first_layer[r], first_layer[r+1]) along one axis, hence the points in them and the nodes of
// those layers. Cuts are placed to balance the point count; each slab is at least
// min_layers_per_rank thick so that a node is touched by the points of at most two ranks.
#pragma once

#include "mpm/grid.h"

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
class SlabPartition
{
public:
  /// Minimum slab thickness in cell layers: the widest stencil (GIMP, 3 nodes, one layer
  /// below a point's cell) reaches 1 layer down and 2 up, so 4 layers keep the node sets of
  /// ranks r-1 and r+1 apart.
  static constexpr int min_layers_per_rank = 4;

  SlabPartition() = default;
  /// One rank owning everything.
  explicit SlabPartition(int axis) : slab_axis(axis), cuts{lowest, highest} {}

  /// Cuts along `axis` balancing `points_per_layer` (one count per cell layer of the grid)
  /// over n_ranks. Throws std::invalid_argument when the grid has fewer than
  /// min_layers_per_rank layers per rank.
  static SlabPartition balanced(int axis, const std::vector<std::uint64_t>& points_per_layer,
                                int n_ranks);

  /// A partition saved with axis() and first_layers() (checkpoints); throws
  /// std::invalid_argument when the cuts are not increasing.
  static SlabPartition from_layers(int axis, const std::vector<int>& first_layers);

  int axis() const { return slab_axis; }
  int n_ranks() const { return static_cast<int>(cuts.size()) - 1; }
  /// First cell layer of each rank, n_ranks + 1 entries (the outer two are open ends).
  const std::vector<int>& first_layers() const { return cuts; }

  /// Rank owning cell (or node) layer `layer`; layers outside the grid belong to the end ranks.
  int rank_of_layer(int layer) const;
  int rank_of_position(const Grid& grid, const Vector3& x) const;
  int rank_of_node(const Grid& grid, std::int64_t key) const;
  /// Cell layer of a position along the axis.
  int layer_of_position(const Grid& grid, const Vector3& x) const;

  /// Node layers the points of `rank` can touch with a stencil reaching `below` layers under
  /// a point's cell and `above` layers over it: [first - below, last + above].
  std::pair<int, int> touched_node_layers(int rank, int below, int above) const;

private:
  static constexpr int lowest = -(1 << 29);
  static constexpr int highest = 1 << 29;
  int slab_axis = 0;
  std::vector<int> cuts{lowest, highest};
};

/// The axis with the most cell layers holding points (ties: the lower axis), so slabs cut
/// across the largest spread of the scene.
int choose_slab_axis(const std::vector<std::vector<std::uint64_t>>& points_per_layer_by_axis);
} // namespace vulnus::mpm
