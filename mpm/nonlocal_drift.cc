// Per-cell sums of the largest changes within the radius, and the per-point test against them.
#include "mpm/nonlocal_drift.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vulnus::mpm
{
namespace
{
constexpr double unbounded = std::numeric_limits<double>::infinity();
}

void NonlocalMeanDrift::reset(const NonlocalNeighbourhood& neighbourhood, const std::size_t n)
{
  previous.assign(n, 0.0);
  previous_counted.assign(n, 0);
  previous_tracked.assign(neighbourhood.n_cells(), 0);
  cell_sum.assign(neighbourhood.n_cells(), 0.0);
  cell_epoch.assign(neighbourhood.n_cells(), 0);
  slack.assign(n, -unbounded);
  sum_at_mean.assign(n, 0.0);
  epoch_at_mean.assign(n, 0);
}

void NonlocalMeanDrift::advance(const NonlocalNeighbourhood& neighbourhood, const double* values,
                                const char* counted, const std::vector<char>& tracked)
{
  const long cells = static_cast<long>(neighbourhood.n_cells());
  std::vector<double> change(cells, unbounded);
#pragma omp parallel for schedule(dynamic, 64)
  for (long c = 0; c < cells; ++c)
  {
    if (!tracked[c])
      continue;
    double largest = 0.0;
    for (std::size_t s = neighbourhood.cell_begin(c); s < neighbourhood.cell_end(c); ++s)
    {
      const std::size_t i = neighbourhood.binned_at(s);
      if (counted[i] && previous_counted[i])
        largest = std::max(largest, std::abs(values[i] - previous[i]));
      else if (counted[i] || previous_counted[i])
        largest = unbounded;
      if (!(largest >= 0.0))
        largest = unbounded;
      previous[i] = values[i];
      previous_counted[i] = counted[i];
    }
    change[c] = previous_tracked[c] ? largest : unbounded;
  }
  previous_tracked = tracked;
  const std::vector<double> reach = neighbourhood.largest_within_the_radius(change);
#pragma omp parallel for schedule(static)
  for (long c = 0; c < cells; ++c)
    if (reach[c] == unbounded)
    {
      cell_sum[c] = 0.0;
      ++cell_epoch[c];
    }
    else
      cell_sum[c] += reach[c];
}

bool NonlocalMeanDrift::may_pass(const std::size_t i, const std::size_t cell,
                                 const double limit) const
{
  if (epoch_at_mean[i] != cell_epoch[cell])
    return true;
  // Room for the rounding of two sums of a few hundred terms and of the running sum.
  const double rounding = 1e-12 * (std::abs(limit) + 1.0) + 1e-14 * cell_sum[cell];
  return !(cell_sum[cell] - sum_at_mean[i] + rounding < slack[i]);
}

void NonlocalMeanDrift::computed(const std::size_t i, const std::size_t cell, const double mean,
                                 const double limit)
{
  slack[i] = limit - mean;
  sum_at_mean[i] = cell_sum[cell];
  epoch_at_mean[i] = cell_epoch[cell];
}
} // namespace vulnus::mpm
