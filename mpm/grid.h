// Structured background grid, of cubic cells or graded (h-wide cells in a fine box, wider ones
// outside: mpm/grid_axis.h), with a sparse set of active nodes: node data is stored only for
// nodes that receive mass this step, found through a dense 4-byte lookup table over the padded
// box (so node storage and node loops follow the particles).
#pragma once

#include "mpm/grid_axis.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
using Vector3 = Eigen::Vector3d;

class Grid
{
public:
  /// Nodes exist from index -padding to n_cells + padding along each axis.
  static constexpr int padding = 2;

  Grid() = default;
  /// `axisymmetric`: x is the radius r >= 0, y the axis, z one cell across the r-y plane
  /// (mpm/axisymmetry.h); shape functions then have no z gradient.
  Grid(const Vector3& domain_min, const Vector3& domain_max, double cell_size,
       bool axisymmetric = false);
  /// A graded grid when `grading.enabled()` (linear shape functions only): cell_size() is then
  /// the finest cell, the fine box's.
  Grid(const Vector3& domain_min, const Vector3& domain_max, double cell_size, bool axisymmetric,
       const GridGrading& grading);

  /// Cells along each axis of the grid over [domain_min, domain_max] (the box is rounded up
  /// to whole cells), without building it.
  static std::array<int, 3> cell_counts(const Vector3& domain_min, const Vector3& domain_max,
                                        double cell_size);

  /// The cells' edge, or on a graded grid the finest cells' edge.
  double cell_size() const { return h; }
  bool axisymmetric() const { return of_revolution; }
  bool graded() const { return is_graded; }
  /// 1 / cell_size(): a uniform grid's shape function gradient scale.
  double inverse_cell_size() const { return inverse_h; }
  /// Width of cell i along `axis` and its inverse (cell_size() on a uniform grid).
  double cell_width(const int axis, const int i) const { return is_graded ? axes[axis].width(i) : h; }
  double inverse_cell_width(const int axis, const int i) const
  {
    return is_graded ? axes[axis].inverse_width(i) : inverse_h;
  }
  /// The widest side of the cell holding x, in the r-y plane on an axisymmetric grid.
  double widest_cell_side(const Vector3& x) const
  {
    Vector3 w, inverse_w;
    locate(x, w, inverse_w);
    return of_revolution ? std::max(w[0], w[1]) : w.maxCoeff();
  }
  /// Coordinate of node i along `axis`.
  double node_coordinate(const int axis, const int i) const
  {
    return is_graded ? axes[axis].node(i) : domain_min[axis] + h * i;
  }
  const Vector3& origin() const { return domain_min; }
  const Vector3& upper_corner() const { return domain_max; }
  const std::array<int, 3>& cells() const { return n_cells; }

  /// Position in cell units: i + (x - x_i) / w_i along each axis in the cell i holding x
  /// ((x - domain minimum) / h on a uniform grid).
  Vector3 to_cell_units(const Vector3& x) const
  {
    if (!is_graded)
      return (x - domain_min) * inverse_h;
    return Vector3(axes[0].to_cell_units(x[0]), axes[1].to_cell_units(x[1]),
                   axes[2].to_cell_units(x[2]));
  }

  /// to_cell_units(x), with the widths of the cell holding x along each axis and their
  /// inverses: one lookup per axis for what a point's stencil needs.
  Vector3 locate(const Vector3& x, Vector3& widths, Vector3& inverse_widths) const
  {
    if (!is_graded)
    {
      widths.setConstant(h);
      inverse_widths.setConstant(inverse_h);
      return (x - domain_min) * inverse_h;
    }
    Vector3 s;
    for (int d = 0; d < 3; ++d)
      s[d] = axes[d].locate(x[d], widths[d], inverse_widths[d]);
    return s;
  }

  /// True when node (i, j, k) lies inside the padded node box.
  bool has_node(const int i, const int j, const int k) const
  {
    return i >= -padding && j >= -padding && k >= -padding && i <= n_cells[0] + padding &&
           j <= n_cells[1] + padding && k <= n_cells[2] + padding;
  }

  std::int64_t node_key(const int i, const int j, const int k) const
  {
    return (i + padding) + n_nodes_box[0] * (std::int64_t(j + padding) +
                                             n_nodes_box[1] * std::int64_t(k + padding));
  }
  std::array<int, 3> node_ijk(std::int64_t key) const;
  Vector3 node_position(std::int64_t key) const;

  /// Sparse active set: each share of points (mpm/point_shares.h) marks the keys it touches
  /// (thread-safe, idempotent); a key marked by two shares becomes contested.
  void mark(const std::int64_t key, const int share)
  {
    std::int32_t* entry = &slot_of_key[key];
    const std::int32_t mine = marked_by_share_0 - share;
    std::int32_t seen = __atomic_load_n(entry, __ATOMIC_RELAXED);
    while (seen != mine && seen != marked_contested)
    {
      const std::int32_t wanted = seen == unmarked ? mine : marked_contested;
      if (__atomic_compare_exchange_n(entry, &seen, wanted, false, __ATOMIC_RELAXED,
                                      __ATOMIC_RELAXED))
        return;
    }
  }
  /// Numbers the marked nodes in key order (and the contested ones among them) after marking
  /// by n_shares shares; returns the count.
  std::size_t number_active_nodes(int n_shares);
  /// Unmarks every active node (cost proportional to the active set).
  void clear_active_nodes();

  /// Slot of an active node, or -1.
  std::int32_t slot(const std::int64_t key) const { return slot_of_key[key]; }
  const std::vector<std::int64_t>& active_keys() const { return active; }
  std::size_t n_active() const { return active.size(); }
  std::size_t n_box_nodes() const { return slot_of_key.size(); }

  /// Shares of points the active set was marked with.
  int n_point_shares() const { return shares; }
  /// Whether the marking also covered the corners of each point's own cell (grid flux's pair
  /// writes there; CPDI's stencil alone can miss them).
  bool point_cells_marked() const { return cells_marked; }
  void set_point_cells_marked(const bool marked) { cells_marked = marked; }
  /// Index of an active node among the contested ones, or -1 when one share alone touches it.
  std::int32_t contested_index(const std::int32_t slot) const { return contested_of_slot[slot]; }
  const std::vector<std::int32_t>& contested_slots() const { return contested; }
  std::size_t n_contested() const { return contested.size(); }

private:
  Vector3 domain_min = Vector3::Zero();
  Vector3 domain_max = Vector3::Zero();
  double h = 1.0;
  double inverse_h = 1.0;
  bool of_revolution = false;
  bool is_graded = false;
  std::array<GridAxis, 3> axes;
  std::array<int, 3> n_cells{{0, 0, 0}};
  std::array<std::int64_t, 3> n_nodes_box{{0, 0, 0}};
  // Before numbering, slot_of_key holds marks: unmarked, contested, or the one share.
  static constexpr std::int32_t unmarked = -1;
  static constexpr std::int32_t marked_contested = -2;
  static constexpr std::int32_t marked_by_share_0 = -3;
  std::vector<std::int32_t> slot_of_key;
  std::vector<std::int64_t> active;
  int shares = 1;
  bool cells_marked = false;
  std::vector<std::int32_t> contested_of_slot;
  std::vector<std::int32_t> contested;

  void allocate_node_box();
};
} // namespace vulnus::mpm
