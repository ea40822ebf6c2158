// What the wound metrics of summary.json need from the target's points, collected from every
// rank without gathering the points themselves: the failed points in full (reference
// position, volume, flag) and the intact ones as a count and a volume.
#pragma once

#include "mpm/solver.h"
#include "analysis/wound_metrics.h"

#include <cstdint>
#include <vector>

namespace vulnus::analysis
{
struct WoundSample
{
  std::vector<mpm::Vector3> failed_position; ///< reference positions of failed target points
  std::vector<double> failed_volume;         ///< their reference volumes, m^3
  std::vector<std::uint8_t> failed_flag;     ///< their failure flags (1, 2, 3), with debris_bit
  std::uint64_t n_intact = 0;                ///< intact target points
  double intact_volume = 0.0;                ///< m^3
  mpm::Vector3 target_lower = mpm::Vector3::Zero(); ///< the target's reference extent, m
  mpm::Vector3 target_upper = mpm::Vector3::Zero();
  mpm::Vector3 projectile_origin = mpm::Vector3::Zero(); ///< its reference mass centre, m
  bool has_target = false;
  double point_spacing = 0.0; ///< m, the largest point spacing of the target's bodies
  std::uint64_t n_points = 0; ///< every point of the scene, all bodies
};

/// Collective; the sample is complete on rank 0 (the others get their own share).
WoundSample collect_wound_sample(const mpm::Solver& solver);

/// A failed target point held outside the MPM solver (a hybrid's far field, on the MPM
/// lattice).
struct FailedPoint
{
  mpm::Vector3 reference_position = mpm::Vector3::Zero(); ///< m
  double reference_volume = 0.0;                          ///< m^3
  std::uint8_t failure = 0;                               ///< its failure flags (1, 2, 3)
};

/// Collective: adds every rank's `points` to the sample's failed points on rank 0.
void add_failed_points(WoundSample& sample, const mpm::RankGroup& ranks,
                       const std::vector<FailedPoint>& points);

/// On rank 0: the sample of the whole scene from that of the part inside its mirror planes
/// (mpm/symmetry_planes.h): the failed points with their images, the intact count and volume
/// and the target's extent likewise, the projectile's origin on the planes. Call it once, after
/// every point has been added.
void complete_by_mirrors(WoundSample& sample, const std::vector<mpm::SymmetryPlane>& planes);

/// Whether the projectile left the target through the exit face of its path: its exit was
/// recorded with its mass centre beyond that face's plane (a ricochet or a sideways exit is
/// not one).
bool left_through_exit_face(const WoundSample& sample, const mpm::Solver& solver);

/// The wound metrics of the sample (on rank 0); the exit wound only for a projectile that
/// left through the exit face. The entrance and exit wounds are measured in the layer of
/// depth `face_layer` below their faces (0: one cell), rounded to whole rows of the target's
/// points (at least one): a 1 mm layer is 1.25 mm deep on a lattice of 0.625 mm.
/// WoundMetrics::face_layer is the depth used. `outline_grid` > 0: the face wounds' outlines
/// on a grid of that spacing (analysis/wound_outline.h).
WoundMetrics wound_metrics_of(const WoundSample& sample, const mpm::Solver& solver,
                              double face_layer, double outline_grid = 0.0);
} // namespace vulnus::analysis
