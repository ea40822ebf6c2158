// The projectile's penetration record: deepest point, stop, and the velocity-depth curve.
#include "mpm/projectile_penetration.h"

#include <stdexcept>

namespace vulnus::mpm
{
void ProjectilePenetration::record(const double time, const double depth, const double speed,
                                   const double stop_speed)
{
  last = {time, depth, speed};
  if (samples.empty() || depth >= samples.back().depth + resolution)
    samples.push_back(last);
  if (depth > max_depth_reached)
  {
    max_depth_reached = depth;
    max_depth_at = time;
  }
  if (!stop_recorded && entered() && speed <= stop_speed)
  {
    stop_recorded = true;
    stop_sample = last;
    if (samples.back().time != time)
      samples.push_back(last);
  }
}

std::vector<double> ProjectilePenetration::packed() const
{
  std::vector<double> values = {resolution,       max_depth_reached, max_depth_at,
                                double(stop_recorded), stop_sample.time, stop_sample.depth,
                                stop_sample.speed, last.time,        last.depth,
                                last.speed};
  for (const PenetrationSample& s : samples)
    values.insert(values.end(), {s.time, s.depth, s.speed});
  return values;
}

void ProjectilePenetration::unpack(const std::vector<double>& values)
{
  constexpr std::size_t head = 10;
  if (values.size() < head || (values.size() - head) % 3 != 0)
    throw std::runtime_error("checkpoint: the projectile's penetration record is malformed");
  resolution = values[0];
  max_depth_reached = values[1];
  max_depth_at = values[2];
  stop_recorded = values[3] != 0.0;
  stop_sample = {values[4], values[5], values[6]};
  last = {values[7], values[8], values[9]};
  samples.clear();
  for (std::size_t i = head; i < values.size(); i += 3)
    samples.push_back({values[i], values[i + 1], values[i + 2]});
}
} // namespace vulnus::mpm
