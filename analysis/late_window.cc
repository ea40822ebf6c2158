// Mean and range of a sampled time series over the second half of its span.
#include "analysis/late_window.h"

#include <algorithm>
#include <stdexcept>

namespace vulnus::analysis
{
LateWindow late_window(const std::vector<double>& times, const std::vector<double>& values)
{
  const std::size_t n = times.size();
  if (n < 2 || values.size() != n || !(times.back() > times.front()))
    throw std::invalid_argument("late_window: needs at least two samples over a positive "
                                "time span, one value per time");
  LateWindow w;
  w.to_time = times.back();
  w.from_time = 0.5 * (times.front() + times.back());
  double integral = 0.0;
  bool first = true;
  for (std::size_t i = 1; i < n; ++i)
  {
    const double t0 = times[i - 1], t1 = times[i];
    if (t1 <= w.from_time || !(t1 > t0))
      continue;
    double v0 = values[i - 1];
    double start = t0;
    if (t0 < w.from_time)
    {
      v0 += (values[i] - v0) * (w.from_time - t0) / (t1 - t0);
      start = w.from_time;
    }
    integral += 0.5 * (v0 + values[i]) * (t1 - start);
    if (first)
      w.min = w.max = v0;
    first = false;
    w.min = std::min({w.min, v0, values[i]});
    w.max = std::max({w.max, v0, values[i]});
  }
  w.mean = integral / (w.to_time - w.from_time);
  return w;
}
} // namespace vulnus::analysis
