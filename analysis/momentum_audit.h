// The momentum audit of a finished run (summary.json "momentum_audit"): what the bodies hold
// now plus what left the grid must equal what they held at the start plus every impulse from
// outside (supports of every face, gravity, the drivers of prescribed rigid motion, material
// added from elsewhere). A run whose balance does not close to `tolerance` of the momentum
// that flowed says so in its warnings.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <optional>
#include <string>

namespace vulnus::analysis
{
struct MomentumAudit
{
  /// Relative tolerance of the balance: round-off of sums over millions of points is about
  /// 1e-12 of them; a lost node impulse or a missed face is far above 1e-6.
  static constexpr double tolerance = 1e-6;

  Eigen::Vector3d initial = Eigen::Vector3d::Zero();  ///< kg m/s, every body at t = 0
  Eigen::Vector3d now = Eigen::Vector3d::Zero();      ///< kg m/s, every body (MPM and FE)
  Eigen::Vector3d removed = Eigen::Vector3d::Zero();  ///< kg m/s, carried off the grid
  Eigen::Vector3d supports = Eigen::Vector3d::Zero(); ///< N s, all faces, MPM and FE
  Eigen::Vector3d external = Eigen::Vector3d::Zero(); ///< N s, gravity and rigid drivers
  Eigen::Vector3d added = Eigen::Vector3d::Zero();    ///< kg m/s, brought in from outside
  /// Sum of the magnitudes of the support impulses added, N s.
  double support_magnitudes = 0.0;

  /// Adds one face's support impulse.
  void add_support(const Eigen::Vector3d& impulse)
  {
    supports += impulse;
    support_magnitudes += impulse.norm();
  }
  /// Magnitude the imbalance is measured against, kg m/s: the largest of the initial
  /// momentum, the sum of the support impulses' magnitudes, the external and added ones.
  double scale() const
  {
    return std::max({initial.norm(), support_magnitudes, external.norm(), added.norm()});
  }

  /// now + removed - (initial + supports + external + added), kg m/s.
  Eigen::Vector3d imbalance() const { return now + removed - (initial + supports + external + added); }
  double relative_imbalance() const { return scale() > 0.0 ? imbalance().norm() / scale() : 0.0; }
  bool closes() const { return relative_imbalance() <= tolerance; }
};

nlohmann::json momentum_audit_json(const MomentumAudit& audit);

/// The warning of a summary whose audit does not close (summary["momentum_audit"]); none when
/// it closes or the summary has no audit.
std::optional<std::string> momentum_audit_warning(const nlohmann::json& summary);
} // namespace vulnus::analysis
