// The late part of a sampled time series: its mean and range over the second half of the run.
// A support's impulse rings with the target's wave round trips, so its end value depends on
// the ring's phase at the last step; the late mean and range do not (docs/far_field.md
// section 2).
#pragma once

#include <vector>

namespace vulnus::analysis
{
struct LateWindow
{
  double from_time = 0.0; ///< s, the middle of the sampled span
  double to_time = 0.0;   ///< s, the last sample
  double mean = 0.0;      ///< time average over [from_time, to_time] (trapezoid rule)
  double min = 0.0;
  double max = 0.0;
};

/// Over the second half of the span of `times` (ascending, the same length as `values`, at
/// least two samples spanning a positive time; else std::invalid_argument). The sample
/// interval straddling the middle is cut there by linear interpolation.
LateWindow late_window(const std::vector<double>& times, const std::vector<double>& values);
} // namespace vulnus::analysis
