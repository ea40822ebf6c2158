// Wound metrics of a failed point set (docs/DESIGN.md section 8), computed on the reference
// (initial) positions of the target's points, so they map which material was destroyed:
//  - failed volume by type (flags 1 matrix, 2 fibers, 3 total);
//  - the wound of a face: the totally failed points within one cell of the face plane;
//    failed area A = (their volume) / (cell size); equivalent diameter sqrt(4 A / pi);
//    aspect ratio sqrt(l1 / l2) of the principal second moments l1 >= l2 of their in-plane
//    positions (volume-weighted), and the major axis direction (eigenvector of l1);
//  - the tract: area of the total-failure cross-section in slices one cell thick along
//    the flight axis, against depth below the entrance face.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace vulnus::analysis
{
using Vector3 = Eigen::Vector3d;

struct FaceWound
{
  std::size_t n_points = 0;
  double area = 0.0;                  ///< m^2
  double equivalent_diameter = 0.0;   ///< m
  double aspect_ratio = 1.0;          ///< >= 1; 1 for a circle (and when fewer than 3 points)
  Vector3 major_axis = Vector3::Zero(); ///< unit, in the face plane
};

struct WoundMetrics
{
  std::array<std::size_t, 4> counts{{0, 0, 0, 0}}; ///< by flag 0..3
  std::array<double, 4> volumes{{0, 0, 0, 0}};     ///< m^3, by flag
  FaceWound entrance;
  FaceWound exit;
  std::vector<double> tract_depth; ///< m, slice centres below the entrance face
  std::vector<double> tract_area;  ///< m^2, total-failure cross-section per slice
};

/// Points of the target: reference positions, reference volumes, failure flags.
/// The flight axis is unit; the entrance face is the plane x . axis = entrance, the exit face
/// x . axis = exit (entrance < exit).
WoundMetrics compute_wound_metrics(const std::vector<Vector3>& reference_positions,
                                   const std::vector<double>& reference_volumes,
                                   const std::vector<std::uint8_t>& flags, const Vector3& axis,
                                   double entrance, double exit, double cell_size);
} // namespace vulnus::analysis
