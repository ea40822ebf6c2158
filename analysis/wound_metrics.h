// Wound metrics of a failed point set (docs/DESIGN.md section 8), computed on the reference
// (initial) positions of the target's points, so they map which material was destroyed.
// The wound is measured on the target's own geometry: the projectile's path (its initial mass
// centre along its initial velocity) enters the target's reference box through one face and
// leaves it through another, whatever the angle of the shot.
//  - failed volume by type (flags 1 matrix, 2 fibers, 3 total);
//  - debris: the failed points that carry no deviatoric stress at the end of the run (flag bit
//    debris_bit), whatever their flag; a matrix-failed point whose fibre is not stretched
//    carries pressure alone, like a totally failed one;
//  - the wound of a face the path crosses: the totally failed points within one cell of the
//    face plane; failed area A = (their volume) / (cell size); equivalent diameter
//    sqrt(4 A / pi); aspect ratio sqrt(l1 / l2) of the principal second moments l1 >= l2 of
//    their positions in the face plane (volume-weighted), and the major axis direction;
//  - the outline of each face wound: the layer's debris smoothed onto a grid of fixed spacing
//    in the face plane, where it reaches one half (analysis/wound_outline.h);
//  - the tract: area of the total-failure (and of the debris) cross-section in slices one cell
//    thick normal to the path, against the distance along the path from the entrance point.
#pragma once

#include "analysis/wound_outline.h"
#include "mpm/target_path.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace vulnus::analysis
{
using Vector3 = Eigen::Vector3d;

/// Set in a point's flag when it failed and carries no deviatoric stress (debris); the low two
/// bits are the paper's failure flag.
constexpr std::uint8_t debris_bit = 0x80;

/// Whether a failed point with this Cauchy stress (Voigt order) is debris: its deviatoric part
/// vanishes to rounding against the stress itself.
bool carries_no_deviatoric_stress(const Eigen::Matrix<double, 6, 1>& stress);

/// Faces of a box: 0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+; -1 none.
const char* box_face_name(int face);

struct FaceWound
{
  int face = -1;                      ///< the box face (-1: no such wound)
  std::size_t n_points = 0;
  double area = 0.0;                  ///< m^2
  double equivalent_diameter = 0.0;   ///< m
  double aspect_ratio = 1.0;          ///< >= 1; 1 for a circle (and when fewer than 3 points)
  Vector3 major_axis = Vector3::Zero(); ///< unit, in the face plane
  FaceOutline outline; ///< the layer's debris smoothed on a fixed grid (not for rings)
};

using mpm::path_through_box;
using mpm::PathThroughBox;

/// What the metrics are measured on.
struct WoundGeometry
{
  Vector3 box_lower = Vector3::Zero(), box_upper = Vector3::Zero(); ///< the target's extent, m
  Vector3 path_origin = Vector3::Zero();                            ///< m
  Vector3 path_direction = Vector3::UnitY();                        ///< unit
  double cell_size = 0.0;                                           ///< m
  /// Depth below the entrance and exit faces of the layer their wounds are measured in, m;
  /// 0: one cell.
  double face_layer = 0.0;
  bool projectile_exited = true; ///< whether an exit wound is measured
  /// The points are rings about the path (an axisymmetric scene): a face wound is round, its
  /// aspect ratio 1 and it has no major axis.
  bool rings_about_path = false;
  /// Spacing of the face planes' grid of the wounds' outlines, m (0: none).
  double outline_spacing = 0.0;
};

struct WoundMetrics
{
  std::array<std::size_t, 4> counts{{0, 0, 0, 0}}; ///< by flag 0..3
  std::array<double, 4> volumes{{0, 0, 0, 0}};     ///< m^3, by flag
  std::size_t debris_count = 0; ///< failed points without deviatoric stress
  double debris_volume = 0.0;   ///< m^3
  PathThroughBox path;
  FaceWound entrance;
  FaceWound exit; ///< face -1 when the projectile did not leave through the exit face
  std::vector<double> tract_depth; ///< m, slice centres along the path from the entrance point
  std::vector<double> tract_area;  ///< m^2, total-failure cross-section per slice
  std::vector<double> debris_tract_area; ///< m^2, debris cross-section per slice
  double face_layer = 0.0;         ///< m, the depth the entrance and exit wounds were measured in
};

/// Points of the target: reference positions, reference volumes, failure flags (with
/// debris_bit where it applies).
WoundMetrics compute_wound_metrics(const std::vector<Vector3>& reference_positions,
                                   const std::vector<double>& reference_volumes,
                                   const std::vector<std::uint8_t>& flags,
                                   const WoundGeometry& geometry);
} // namespace vulnus::analysis
