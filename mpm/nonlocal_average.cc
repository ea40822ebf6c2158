// Binning by reference position (a counting sort over a dense box of cells) and the means.
#include "mpm/nonlocal_average.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vulnus::mpm
{
NonlocalNeighbourhood::NonlocalNeighbourhood(const Particles& all, const std::size_t begin,
                                             const std::size_t end, const double l)
  : points(all), first(begin), radius(l)
{
  if (!(l > 0.0))
    throw std::invalid_argument("nonlocal neighbourhood: the radius must be positive");
  if (end <= begin)
  {
    cell_start.assign(2, 0);
    return;
  }
  Vector3f lower = points.reference_position[begin], upper = lower;
  for (std::size_t p = begin; p < end; ++p)
  {
    lower = lower.cwiseMin(points.reference_position[p]);
    upper = upper.cwiseMax(points.reference_position[p]);
  }
  origin = lower;
  for (int d = 0; d < 3; ++d)
    n[d] = static_cast<std::size_t>(std::floor((upper[d] - lower[d]) * reach / l)) + 1;
  const std::size_t n_all = n[0] * n[1] * n[2];
  if (n_all > 64 * (end - begin) + 1000000)
    throw std::invalid_argument("nonlocal neighbourhood: " + std::to_string(n_all) +
                                " cells of edge " + std::to_string(l / reach) + " m for " +
                                std::to_string(end - begin) + " points; the radius is too small");
  cell_of_point.resize(end - begin);
  cell_start.assign(n_all + 1, 0);
  for (std::size_t p = begin; p < end; ++p)
  {
    const std::size_t c = cell_index(cell_coordinates(points.reference_position[p]));
    cell_of_point[p - begin] = c;
    ++cell_start[c + 1];
  }
  for (std::size_t c = 0; c < n_all; ++c)
    cell_start[c + 1] += cell_start[c];
  order.resize(end - begin);
  std::vector<std::size_t> filled(cell_start.begin(), cell_start.end() - 1);
  for (std::size_t p = begin; p < end; ++p)
    order[filled[cell_of_point[p - begin]]++] = p;
  position.resize(order.size());
  volume.resize(order.size());
  for (std::size_t s = 0; s < order.size(); ++s)
  {
    position[s] = points.reference_position[order[s]];
    volume[s] = static_cast<float>(points.reference_volume[order[s]]);
  }
}

std::array<int, 3> NonlocalNeighbourhood::cell_coordinates(const Vector3f& x) const
{
  std::array<int, 3> c;
  for (int d = 0; d < 3; ++d)
    c[d] = std::clamp(static_cast<int>(std::floor((x[d] - origin[d]) * reach / radius)), 0,
                      static_cast<int>(n[d]) - 1);
  return c;
}

std::vector<NonlocalNeighbour> NonlocalNeighbourhood::neighbours(const std::size_t p) const
{
  std::vector<NonlocalNeighbour> list;
  const Vector3f& x = points.reference_position[p];
  const std::array<int, 3> c = cell_coordinates(x);
  const double edge = radius / reach, radius_squared = radius * radius;
  const double inverse_radius_squared = 1.0 / radius_squared;
  auto low = [&](const int d) { return std::max(c[d] - reach, 0); };
  auto high = [&](const int d) { return std::min(c[d] + reach, static_cast<int>(n[d]) - 1); };
  // Squared distance along axis d from x to the nearest face of cell `cell` (0 in its own).
  auto gap_squared = [&](const int d, const int cell) {
    const double lower = origin[d] + cell * edge, upper = lower + edge;
    const double gap = cell < c[d] ? x[d] - upper : cell > c[d] ? lower - x[d] : 0.0;
    return gap > 0.0 ? gap * gap : 0.0;
  };
  for (int k = low(2); k <= high(2); ++k)
    for (int j = low(1); j <= high(1); ++j)
    {
      const double across = gap_squared(1, j) + gap_squared(2, k);
      if (across >= radius_squared)
        continue;
      int first_cell = low(0), last_cell = high(0);
      while (first_cell < c[0] && across + gap_squared(0, first_cell) >= radius_squared)
        ++first_cell;
      while (last_cell > c[0] && across + gap_squared(0, last_cell) >= radius_squared)
        --last_cell;
      const std::size_t row_begin = cell_start[cell_index({first_cell, j, k})];
      const std::size_t row_end = cell_start[cell_index({last_cell, j, k}) + 1];
      for (std::size_t s = row_begin; s < row_end; ++s)
      {
        const double r2 = (position[s] - x).squaredNorm() * inverse_radius_squared;
        if (r2 < 1.0)
          list.push_back({static_cast<std::uint32_t>(s),
                          static_cast<float>((1.0 - r2) * (1.0 - r2) * volume[s])});
      }
    }
  return list;
}

std::array<double, 2> NonlocalNeighbourhood::list_means(const std::vector<NonlocalNeighbour>& list,
                                                        const double* first_values,
                                                        const double* second_values,
                                                        const char* include)
{
  double first = 0.0, second = 0.0, weights = 0.0;
  for (const NonlocalNeighbour& q : list)
    if (include[q.sorted])
    {
      const double w = q.weight;
      first += w * first_values[q.sorted];
      second += w * second_values[q.sorted];
      weights += w;
    }
  return weights > 0.0 ? std::array<double, 2>{first / weights, second / weights}
                       : std::array<double, 2>{0.0, 0.0};
}

double NonlocalNeighbourhood::list_mean(const std::vector<NonlocalNeighbour>& list,
                                        const double* values, const char* include)
{
  double sum = 0.0, weights = 0.0;
  for (const NonlocalNeighbour& q : list)
    if (include[q.sorted])
    {
      const double w = q.weight;
      sum += w * values[q.sorted];
      weights += w;
    }
  return weights > 0.0 ? sum / weights : 0.0;
}

double NonlocalNeighbourhood::mean(const std::size_t p, const double* values,
                                   const char* include) const
{
  return list_mean(neighbours(p), values, include);
}

std::array<double, 2> NonlocalNeighbourhood::means(const std::size_t p, const double* first_values,
                                                   const double* second_values,
                                                   const char* include) const
{
  return list_means(neighbours(p), first_values, second_values, include);
}

namespace
{
/// Per cell of an n[0] x n[1] x n[2] box (x fastest), the largest value over the cells within
/// `reach` along every axis (separable: along x, then y, then z).
template <class T>
std::vector<T> largest_nearby(std::vector<T> in, const std::array<std::size_t, 3>& n,
                              const std::size_t reach)
{
  std::vector<T> out(in.size());
  const std::array<std::size_t, 3> stride{{1, n[0], n[0] * n[1]}};
  for (int d = 0; d < 3; ++d)
  {
    // Lines along d, each given by its first cell.
    const int a = d == 0 ? 1 : 0, b = d == 2 ? 1 : 2;
    const long lines = static_cast<long>(n[a] * n[b]);
#pragma omp parallel for schedule(static)
    for (long line = 0; line < lines; ++line)
    {
      const std::size_t start = (static_cast<std::size_t>(line) % n[a]) * stride[a] +
                                (static_cast<std::size_t>(line) / n[a]) * stride[b];
      for (std::size_t along = 0; along < n[d]; ++along)
      {
        const std::size_t high = std::min(along + reach, n[d] - 1);
        T largest = in[start + along * stride[d]];
        for (std::size_t m = along > reach ? along - reach : 0; m <= high; ++m)
          largest = std::max(largest, in[start + m * stride[d]]);
        out[start + along * stride[d]] = largest;
      }
    }
    std::swap(in, out);
  }
  return in;
}
} // namespace

std::vector<double>
NonlocalNeighbourhood::largest_within_the_radius(const std::vector<double>& per_cell) const
{
  return largest_nearby(per_cell, n, reach);
}

std::vector<char> NonlocalNeighbourhood::grown_by_the_radius(const std::vector<char>& flags) const
{
  return largest_nearby(flags, n, reach);
}
} // namespace vulnus::mpm
