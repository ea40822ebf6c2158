// When the next periodic output is due: every `interval` of simulated time from t = 0
// (interval 0: only the first and the final state).
#pragma once

namespace vulnus::simulator
{
class OutputSchedule
{
public:
  OutputSchedule(double interval, double end_time)
      : interval(interval), next(interval > 0 ? interval : 2 * end_time)
  {
  }

  bool due(const double time) const { return time >= next * (1 - 1e-12); }
  void advance() { next += interval; }

  double next_time() const { return next; }
  void set_next_time(const double t) { next = t; }

private:
  double interval;
  double next;
};
} // namespace vulnus::simulator
