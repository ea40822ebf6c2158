// Slab cuts balanced by point count, and the owner of a layer, point or node.
#include "mpm/slab_partition.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace vulnus::mpm
{
SlabPartition SlabPartition::balanced(const int axis,
                                      const std::vector<std::uint64_t>& points_per_layer,
                                      const int n_ranks)
{
  const int n_layers = static_cast<int>(points_per_layer.size());
  if (n_ranks < 1)
    throw std::invalid_argument("slab partition: at least one rank needed");
  if (n_layers < n_ranks * min_layers_per_rank)
    throw std::invalid_argument(
      "distributed MPM: the grid has " + std::to_string(n_layers) + " cell layers along axis " +
      std::to_string(axis) + ", fewer than " + std::to_string(min_layers_per_rank) +
      " per rank for " + std::to_string(n_ranks) +
      " ranks; run on fewer ranks or use smaller cells");
  SlabPartition p(axis);
  p.cuts.assign(n_ranks + 1, 0);
  p.cuts.front() = lowest;
  p.cuts.back() = highest;
  std::uint64_t total = 0;
  for (const std::uint64_t n : points_per_layer)
    total += n;
  std::uint64_t below = 0; // points in layers [0, layer)
  int layer = 0;
  for (int r = 1; r < n_ranks; ++r)
  {
    // First layer where the points below reach r / n_ranks of the total, within the room the
    // minimum thickness leaves on both sides.
    const double target = double(total) * r / n_ranks;
    const int earliest = (r == 1 ? 0 : p.cuts[r - 1]) + min_layers_per_rank;
    const int latest = n_layers - (n_ranks - r) * min_layers_per_rank;
    while (layer < latest && (layer < earliest || double(below) < target))
      below += points_per_layer[layer++];
    p.cuts[r] = layer;
  }
  return p;
}

SlabPartition SlabPartition::from_layers(const int axis, const std::vector<int>& first_layers)
{
  if (axis < 0 || axis > 2 || first_layers.size() < 2 || first_layers.front() != lowest ||
      first_layers.back() != highest ||
      !std::is_sorted(first_layers.begin(), first_layers.end(), std::less_equal<int>()))
    throw std::invalid_argument("slab partition: axis or cuts are malformed");
  SlabPartition p(axis);
  p.cuts = first_layers;
  return p;
}

int SlabPartition::rank_of_layer(const int layer) const
{
  // cuts[1..n-1] are increasing; the owner is the last rank whose first layer is <= layer.
  const auto it = std::upper_bound(cuts.begin() + 1, cuts.end() - 1, layer);
  return static_cast<int>(it - (cuts.begin() + 1));
}

int SlabPartition::layer_of_position(const Grid& grid, const Vector3& x) const
{
  const double s = (x[slab_axis] - grid.origin()[slab_axis]) * grid.inverse_cell_size();
  const double clamped = std::clamp(s, double(lowest), double(highest));
  return static_cast<int>(std::floor(clamped)); // NaN positions are reported by check_state
}

int SlabPartition::rank_of_position(const Grid& grid, const Vector3& x) const
{
  return rank_of_layer(layer_of_position(grid, x));
}

int SlabPartition::rank_of_node(const Grid& grid, const std::int64_t key) const
{
  return rank_of_layer(grid.node_ijk(key)[slab_axis]);
}

std::pair<int, int> SlabPartition::touched_node_layers(const int rank, const int below,
                                                       const int above) const
{
  return {cuts[rank] == lowest ? lowest : cuts[rank] - below,
          cuts[rank + 1] == highest ? highest : cuts[rank + 1] - 1 + above};
}

int choose_slab_axis(const std::vector<std::vector<std::uint64_t>>& points_per_layer_by_axis)
{
  int best = 0;
  long best_count = -1;
  for (std::size_t a = 0; a < points_per_layer_by_axis.size(); ++a)
  {
    const auto& layers = points_per_layer_by_axis[a];
    const long occupied = std::count_if(layers.begin(), layers.end(),
                                        [](const std::uint64_t n) { return n > 0; });
    if (occupied > best_count)
    {
      best = static_cast<int>(a);
      best_count = occupied;
    }
  }
  return best;
}
} // namespace vulnus::mpm
