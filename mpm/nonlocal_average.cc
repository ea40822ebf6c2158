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
  const double inverse_radius_squared = 1.0 / (radius * radius);
  auto low = [&](const int d) { return std::max(c[d] - reach, 0); };
  auto high = [&](const int d) { return std::min(c[d] + reach, static_cast<int>(n[d]) - 1); };
  for (int k = low(2); k <= high(2); ++k)
    for (int j = low(1); j <= high(1); ++j)
    {
      const std::size_t row_begin = cell_start[cell_index({low(0), j, k})];
      const std::size_t row_end = cell_start[cell_index({high(0), j, k}) + 1];
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

std::vector<char> NonlocalNeighbourhood::grown_by_the_radius(const std::vector<char>& flags) const
{
  std::vector<char> grown(flags.size(), 0);
  const std::size_t r = reach;
  for (std::size_t k = 0; k < n[2]; ++k)
    for (std::size_t j = 0; j < n[1]; ++j)
      for (std::size_t i = 0; i < n[0]; ++i)
      {
        if (!flags[cell_index({static_cast<int>(i), static_cast<int>(j), static_cast<int>(k)})])
          continue;
        for (std::size_t kk = k > r ? k - r : 0; kk <= std::min(k + r, n[2] - 1); ++kk)
          for (std::size_t jj = j > r ? j - r : 0; jj <= std::min(j + r, n[1] - 1); ++jj)
            for (std::size_t ii = i > r ? i - r : 0; ii <= std::min(i + r, n[0] - 1); ++ii)
              grown[ii + n[0] * (jj + n[1] * kk)] = 1;
      }
  return grown;
}
} // namespace vulnus::mpm
