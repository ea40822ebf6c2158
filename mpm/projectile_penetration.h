// How deep the projectile goes and how fast: its nose's depth along the flight axis below the
// target's entrance plane and its mass-centre speed along the axis, step by step; the deepest
// point it reached; and when it stopped or turned back (Time/Stop when projectile stops).
#pragma once

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
/// One point of the velocity-depth curve.
struct PenetrationSample
{
  double time = 0.0;  ///< s
  double depth = 0.0; ///< m, nose below the entrance plane
  double speed = 0.0; ///< m/s, mass-centre velocity along the flight axis
};

/// The record. Depth is measured from the plane through the target's point nearest the
/// projectile along the flight axis (for a normal shot, the entrance face's points; add half a
/// point spacing for the face itself, as the nose adds it for the projectile's front).
class ProjectilePenetration
{
public:
  /// `resolution`: the depth step between samples of the curve (m).
  explicit ProjectilePenetration(double resolution = 0.0) : resolution(resolution) {}

  /// After every step: the nose's depth (m) and the forward speed (m/s) at `time`. The
  /// projectile counts as stopped the first time its speed is at most `stop_speed` once the
  /// nose has entered the target (depth > 0): at rest, or turning back.
  void record(double time, double depth, double speed, double stop_speed);

  bool entered() const { return max_depth_reached > 0.0; }
  bool stopped() const { return stop_recorded; }
  double max_depth() const { return max_depth_reached; }
  double max_depth_time() const { return max_depth_at; }
  /// The sample at which it stopped (valid when stopped()).
  const PenetrationSample& stop() const { return stop_sample; }
  /// The curve: the first sample, one each time the depth grew by the resolution, and the
  /// latest state.
  const std::vector<PenetrationSample>& curve() const { return samples; }
  const PenetrationSample& latest() const { return last; }

  /// Checkpoints: the record as numbers, and back.
  std::vector<double> packed() const;
  void unpack(const std::vector<double>& values);

private:
  double resolution;
  double max_depth_reached = 0.0;
  double max_depth_at = 0.0;
  bool stop_recorded = false;
  PenetrationSample stop_sample;
  PenetrationSample last;
  std::vector<PenetrationSample> samples;
};
} // namespace vulnus::mpm
