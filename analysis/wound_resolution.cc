// The resolution rule of the wound figures: narrowest width in cells against cells_needed; in a
// fibred target only the matrix-failed volume is judged by its width.
#include "analysis/wound_resolution.h"

#include <cmath>
#include <numeric>

namespace vulnus::analysis
{
namespace
{
/// The equivalent diameter of a region's mean cross-section along the path, m.
double mean_diameter(const std::vector<double>& areas)
{
  if (areas.empty())
    return 0.0;
  const double mean = std::accumulate(areas.begin(), areas.end(), 0.0) / areas.size();
  return std::sqrt(4.0 * mean / M_PI);
}

/// A face region's narrowest width: the minor axis of the ellipse of its area and aspect ratio.
double minor_width(const double equivalent_diameter, const double aspect_ratio)
{
  return aspect_ratio > 0.0 ? equivalent_diameter / std::sqrt(aspect_ratio) : equivalent_diameter;
}
} // namespace

std::vector<FigureResolution> resolve_wound_figures(const WoundMetrics& m, const double cell_size,
                                                    const bool fibred_target)
{
  std::vector<FigureResolution> out;
  // A region that is empty (no debris, no exit wound) has no figure to judge.
  auto by_width = [&](const std::string& figure, const double width) {
    if (!(width > 0.0))
      return;
    FigureResolution r;
    r.figure = figure;
    r.cells_across = cell_size > 0.0 ? width / cell_size : 0.0;
    r.resolved = r.cells_across >= cells_needed;
    if (!r.resolved)
      r.reason = "its region spans fewer than the cells needed";
    out.push_back(r);
  };
  // In a fibred target only the matrix-failed volume converges; the rest is judged by why not.
  auto fibred = [&](const std::string& figure, const double width, const char* why) {
    if (!fibred_target || !(width > 0.0))
      return by_width(figure, width);
    FigureResolution r;
    r.figure = figure;
    r.cells_across = cell_size > 0.0 ? width / cell_size : 0.0;
    r.reason = why;
    out.push_back(r);
  };
  const char* flag_reason = "a failure flag of a fibred target: it records a limit passed, not "
                            "the tissue's state, and does not converge";
  const char* drift_reason = "in a fibred target it drifts under refinement however many cells "
                             "span it (docs/locking.md); quote it with its cell";
  auto flag = [&](const std::string& figure, const double width) {
    fibred(figure, width, flag_reason);
  };
  auto drifts = [&](const std::string& figure, const double width) {
    fibred(figure, width, drift_reason);
  };
  const double debris_width = mean_diameter(m.debris_tract_area);
  drifts("debris", debris_width);
  drifts("tract.debris_area_m2", debris_width);
  const double length = m.path.hits ? m.path.length() : 0.0;
  const double failed_volume = m.volumes[1] + m.volumes[2] + m.volumes[3];
  by_width("failed_volume_m3.matrix",
           length > 0.0 ? std::sqrt(4.0 * failed_volume / length / M_PI) : 0.0);
  const double total_width = mean_diameter(m.tract_area);
  flag("failed_volume_m3.total", total_width);
  if (m.volumes[2] > 0.0)
    flag("failed_volume_m3.fiber", total_width);
  flag("tract.area_m2", total_width);
  for (const auto& [name, wound] : {std::pair<std::string, const FaceWound*>{"entrance_wound", &m.entrance},
                                    {"exit_wound", &m.exit}})
  {
    if (wound->face < 0)
      continue;
    if (wound->n_points > 0)
      flag(name, minor_width(wound->equivalent_diameter, wound->aspect_ratio));
    if (wound->outline.measured)
      drifts(name + ".outline",
               minor_width(wound->outline.equivalent_diameter, wound->outline.aspect_ratio));
  }
  return out;
}
} // namespace vulnus::analysis
