// When the next periodic output is due: every `interval` of simulated time from t = 0
// (interval 0: only the first and the final state).
#pragma once

#include <limits>

namespace vulnus::simulator
{
class OutputSchedule
{
public:
  explicit OutputSchedule(double interval)
      : interval(interval), next(interval > 0 ? interval : std::numeric_limits<double>::infinity())
  {
  }

  bool due(const double time) const { return time >= next * (1 - 1e-12); }
  void advance() { next += interval; }

  double next_time() const { return next; }
  /// From a checkpoint. Without an interval nothing periodic is due, whatever the checkpoint
  /// saved (an earlier build saved twice the run's end time, which a longer run reaches).
  void set_next_time(const double t)
  {
    if (interval > 0)
      next = t;
  }

private:
  double interval;
  double next;
};
} // namespace vulnus::simulator
