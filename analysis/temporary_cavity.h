// The temporary cavity along the projectile's path: how far the target's material stands off
// the path, slice by slice, while the projectile passes; its largest size and when it peaked.
#pragma once

#include "mpm/solver.h"

#include <array>
#include <cstddef>
#include <vector>

namespace vulnus::analysis
{
/// Slices one `thickness` thick normal to the path (the projectile's initial mass centre along
/// its initial velocity), from the path's entrance point on the target's surface to its exit
/// point. In each slice and in each of `sectors` equal angular sectors around the path, the
/// wall is the nearest point of the target that still carries stress (totally failed debris
/// is not wall) to the path, less half a point spacing (a point's own extent); a point counts
/// in every slice and sector within one point spacing of it, so that the wall does not jump
/// out where the points of a bin have moved into its neighbour. The cavity's area is the sum of the
/// sectors' discs, pi r_i^2 / sectors; its diameter the equivalent one, sqrt(4 A / pi). No
/// wall is farther than the grid's boundary along the sector's middle direction, so a sector
/// emptied to the edge (gelatin splashed out of the entrance) counts as open to the edge, not
/// beyond it; in a hybrid the far field's material begins where the MPM points end, and no
/// wall is farther than their box. For every slice the largest diameter over the samples
/// and its time are kept, beside the latest. Near the path a sector is narrower than the
/// point spacing, so undisturbed material already measures about 2.7 point spacings: the
/// first sample's largest diameter is kept as the measure's floor (resolution_floor()).
class TemporaryCavity
{
public:
  static constexpr std::size_t sectors = 16;

  struct Slice
  {
    double depth = 0.0;        ///< m, the slice's middle below the entrance face
    double diameter = 0.0;     ///< m, latest sample
    double max_diameter = 0.0; ///< m, largest sample
    double max_time = 0.0;     ///< s, when it was largest
    /// Every sector held the target's material at the first sample: the slice lies inside
    /// the target. Slices cut by an oblique face are not: they are left out of the largest
    /// diameter and of the floor.
    bool inside_target = true;
  };

  TemporaryCavity() = default;
  /// The path of `solver`'s projectile through its target (collective).
  explicit TemporaryCavity(const mpm::Solver& solver);

  /// Collective: measures the cavity at the solver's current state.
  void sample(const mpm::Solver& solver);

  bool active() const { return !slices.empty(); }
  const std::vector<Slice>& profile() const { return slices; }
  double slice_thickness() const { return thickness; }
  /// The largest diameter of any slice inside the target, its depth and time.
  const Slice& largest() const;
  /// The largest diameter of the first sample (m): cavities below it are not resolved.
  double resolution_floor() const { return floor_diameter; }

  std::vector<double> packed() const;
  void unpack(const std::vector<double>& values);

private:
  mpm::Vector3 origin = mpm::Vector3::Zero(); ///< the path at the entrance face
  mpm::Vector3 axis = mpm::Vector3::UnitY();
  mpm::Vector3 across_1 = mpm::Vector3::UnitX(), across_2 = mpm::Vector3::UnitZ();
  double thickness = 0.0;
  double half_spacing = 0.0;
  double radius_cap = 0.0;

  /// From the path to the boundary of a box along each sector's middle direction.
  std::array<double, sectors> distances_to_the_box(const mpm::Vector3& lower,
                                                   const mpm::Vector3& upper) const;
  double floor_diameter = -1.0; ///< set by the first sample
  std::vector<Slice> slices;
  std::vector<double> nearest; ///< per slice and sector, this sample's wall distance
};
} // namespace vulnus::analysis
