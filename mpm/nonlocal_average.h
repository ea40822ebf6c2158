// Nonlocal means over material points: the mean of a point field over the points within a
// radius l of a point in the reference configuration, weighted by the bell function
// (1 - r^2 / l^2)^2 and the points' reference volumes. The points are binned by reference
// position into cubic cells of edge l/2, so a mean visits the 125 cells around its point.
#pragma once

#include "mpm/particles.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
/// A point within the radius of another and its weight (bell function times reference
/// volume, in single precision like the volumes), by its position in cell order.
struct NonlocalNeighbour
{
  std::uint32_t sorted = 0;
  float weight = 0.0f;
};

class NonlocalNeighbourhood
{
public:
  /// Bins points [begin, end) of `points` (one body) by reference position.
  NonlocalNeighbourhood(const Particles& points, std::size_t begin, std::size_t end,
                        double radius);

  /// The weighted mean of a field over the binned points q with include set that lie within
  /// the radius of point p (p itself counts when included); 0 when there is none. `values`
  /// and `include` are in cell order (in_cell_order), so the loop reads memory in sequence.
  double mean(std::size_t p, const double* values, const char* include) const;
  /// The means of two fields in one pass.
  std::array<double, 2> means(std::size_t p, const double* first_values,
                              const double* second_values, const char* include) const;
  /// The binned points within the radius of point p with their weights, row by row of the
  /// cells around it; mean() and means() are list_mean() and list_means() over it.
  std::vector<NonlocalNeighbour> neighbours(std::size_t p) const;
  /// means() over a list from neighbours().
  static std::array<double, 2> list_means(const std::vector<NonlocalNeighbour>& list,
                                          const double* first_values,
                                          const double* second_values, const char* include);
  static double list_mean(const std::vector<NonlocalNeighbour>& list, const double* values,
                          const char* include);
  /// A field given per binned point (index q - begin) rearranged into cell order.
  template <class T>
  std::vector<T> in_cell_order(const T* values) const
  {
    std::vector<T> sorted(order.size());
    const long n_sorted = static_cast<long>(order.size());
#pragma omp parallel for schedule(static)
    for (long s = 0; s < n_sorted; ++s)
      sorted[s] = values[order[s] - first];
    return sorted;
  }

  std::size_t n_cells() const { return cell_start.size() - 1; }
  /// Index of the cell holding binned point p.
  std::size_t cell_of(std::size_t p) const { return cell_of_point[p - first]; }
  /// The binned points of cell c are binned_at(s) for s in [cell_begin(c), cell_end(c)),
  /// each as its index q - begin.
  std::size_t cell_begin(std::size_t c) const { return cell_start[c]; }
  std::size_t cell_end(std::size_t c) const { return cell_start[c + 1]; }
  std::size_t binned_at(std::size_t s) const { return order[s] - first; }
  /// Per cell, the largest of a per-cell field over the cells within two cells of it (which
  /// hold every point within the radius of the cell's points).
  std::vector<double> largest_within_the_radius(const std::vector<double>& per_cell) const;
  /// Flags every cell that holds a point within the radius of a point in a flagged cell (the
  /// cells within two cells of it).
  std::vector<char> grown_by_the_radius(const std::vector<char>& cell_flags) const;

private:
  static constexpr int reach = 2; ///< cells per radius
  std::array<int, 3> cell_coordinates(const Vector3f& x) const;
  std::size_t cell_index(const std::array<int, 3>& c) const
  {
    return static_cast<std::size_t>(c[0]) +
           n[0] * (static_cast<std::size_t>(c[1]) + n[1] * static_cast<std::size_t>(c[2]));
  }

  const Particles& points;
  std::size_t first = 0;
  double radius = 0.0;
  Vector3f origin = Vector3f::Zero();
  std::array<std::size_t, 3> n{{1, 1, 1}};
  std::vector<std::size_t> cell_of_point; ///< per binned point
  std::vector<std::size_t> cell_start;    ///< per cell, into order (plus the end)
  std::vector<std::size_t> order;         ///< binned point indices, cell by cell
  std::vector<Vector3f> position;         ///< reference positions in cell order
  std::vector<float> volume;              ///< reference volumes in cell order
};
} // namespace vulnus::mpm
