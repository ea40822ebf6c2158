// The outline of a face wound: the debris indicator of the points in the face layer, smoothed
// onto a square grid of fixed spacing in the face plane (quadratic B-splines), and the region
// where it reaches one half. Its area, equivalent diameter, aspect ratio and axis are measured
// on a grid fixed in space whatever the cell, failed points scattered around the wound stay
// below one half and leave it (the points' own second moments weigh them by their distance
// squared), and small intact islands inside the wound do not open holes in it.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vulnus::analysis
{
struct FaceOutline
{
  bool measured = false;          ///< false: no debris in the layer, or no grid asked for
  double grid_spacing = 0.0;      ///< m
  double area = 0.0;              ///< m^2, where the smoothed indicator is at least 1/2
  double equivalent_diameter = 0.0; ///< m, sqrt(4 area / pi)
  double aspect_ratio = 1.0;      ///< sqrt(l1 / l2) of the region's principal second moments
  Eigen::Vector3d major_axis = Eigen::Vector3d::Zero(); ///< unit, in the face plane
};

/// The outline on the face `face` of the box (0 x-, 1 x+, ... 5 z+) whose plane is at `plane`
/// along its normal: the points within `layer` inside it whose flag has `indicator_bit`
/// contribute their volume. Their indicator is normalised by the layer's full volume per grid
/// node (H^2 layer), so intact points need not be given. `spacing` H > 0.
FaceOutline face_outline(const std::vector<Eigen::Vector3d>& x, const std::vector<double>& volume,
                         const std::vector<std::uint8_t>& flags, std::uint8_t indicator_bit,
                         int face, double plane, double layer, double spacing);
} // namespace vulnus::analysis
