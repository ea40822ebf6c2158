// Re-binning a depth profile onto other slices (overlap-weighted means).
#include "analysis/slice_profiles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vulnus::analysis
{
double slice_thickness(const std::vector<double>& centres)
{
  return centres.size() > 1 ? centres[1] - centres[0] : 2.0 * centres.front();
}

std::vector<std::optional<double>> rebin_slices(const std::vector<double>& from_depth,
                                                const std::vector<double>& from_value,
                                                const std::vector<double>& to_depth)
{
  if (from_depth.size() != from_value.size())
    throw std::invalid_argument("rebin_slices: as many values as slices are needed");
  std::vector<std::optional<double>> result(to_depth.size());
  if (from_depth.empty() || to_depth.empty())
    return result;
  const double from_half = 0.5 * slice_thickness(from_depth),
               to_half = 0.5 * slice_thickness(to_depth);
  for (std::size_t i = 0; i < to_depth.size(); ++i)
  {
    double weighted = 0.0, covered = 0.0;
    for (std::size_t j = 0; j < from_depth.size(); ++j)
    {
      const double overlap = std::min(to_depth[i] + to_half, from_depth[j] + from_half) -
                             std::max(to_depth[i] - to_half, from_depth[j] - from_half);
      if (overlap > 0.0)
      {
        weighted += overlap * from_value[j];
        covered += overlap;
      }
    }
    if (covered >= (1.0 - 1e-6) * 2.0 * to_half)
      result[i] = weighted / covered;
  }
  return result;
}

bool same_slices(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
    return false;
  if (a.empty())
    return true;
  const double scale = std::max(std::abs(slice_thickness(a)), std::abs(slice_thickness(b)));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] - b[i]) > 1e-9 * scale)
      return false;
  return true;
}
} // namespace vulnus::analysis
