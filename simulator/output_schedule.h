// When the next periodic output is due: every `interval` of simulated time from t = 0
// (interval 0: only the first and the final state).
#pragma once

#include <cmath>
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
  /// On a restart at time `now`, from the next output time the checkpoint saved. Without an
  /// interval nothing periodic is due, whatever the checkpoint holds. With one, the saved time
  /// holds if it is the next on this interval; otherwise (the interval changed, or the run had
  /// none) the next multiple of the interval after `now` is.
  void resume(const double saved_next, const double now)
  {
    if (!(interval > 0))
      return;
    if (std::isfinite(saved_next) && saved_next > now && saved_next <= now + interval * (1 + 1e-9))
      next = saved_next;
    else
      next = (std::floor(now / interval * (1 + 1e-12)) + 1) * interval;
  }

private:
  double interval;
  double next;
};
} // namespace vulnus::simulator
