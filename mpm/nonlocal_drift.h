// Which nonlocal means can have reached their limit since they were last computed. A mean
// over a fixed set of points with fixed weights moves by at most the largest change of its
// values, so a point whose last mean lay `slack` below the limit cannot pass it while the
// changes within its radius, added up step by step, stay below that slack. Changes are
// taken per binning cell (the largest in the cell), spread to the cells within the radius and
// added up per cell; a point remembers its cell's sum when its mean is computed.
#pragma once

#include "mpm/nonlocal_average.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
class NonlocalMeanDrift
{
public:
  /// Forgets every mean (each must be computed again).
  void reset(const NonlocalNeighbourhood& neighbourhood, std::size_t n_points);

  /// Books one step. values and counted are per point (index q - begin); values are the
  /// ones the means use in the `tracked` cells (flag per cell), unknown elsewhere. A change
  /// is unbounded in a cell not tracked now or at the last step, and where a point stopped
  /// counting in the means; such a cell restarts the sums within its radius.
  void advance(const NonlocalNeighbourhood& neighbourhood, const double* values,
               const char* counted, const std::vector<char>& tracked);

  /// Whether the mean at point i (in cell `cell`) may have passed `limit` since it was last
  /// computed.
  bool may_pass(std::size_t i, std::size_t cell, double limit) const;
  /// Records the mean just computed at point i.
  void computed(std::size_t i, std::size_t cell, double mean, double limit);

private:
  std::vector<double> previous;       ///< per point, in the cells tracked at the last step
  std::vector<char> previous_counted; ///< likewise
  std::vector<char> previous_tracked; ///< per cell
  std::vector<double> cell_sum;       ///< per cell: the changes within the radius, added up
  std::vector<std::uint32_t> cell_epoch; ///< per cell: restarts of that sum
  std::vector<double> slack;          ///< per point: limit - last mean; -inf before a mean
  std::vector<double> sum_at_mean;
  std::vector<std::uint32_t> epoch_at_mean;
};
} // namespace vulnus::mpm
