// The smoothed outline of a face wound (analysis/wound_outline.h) on hand-built point sets: a
// disc and an ellipse of debris give their diameter, axes ratio and axis; shifting the points'
// lattice by half a spacing leaves the outline where it was; failed points scattered around
// the wound hardly move it.
#include "analysis/wound_metrics.h"
#include "point_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace vulnus;
using namespace vulnus::analysis;

namespace
{
using test::PointSet;

/// A 40 x 4 x 40 mm slab (y through the thickness) of points at spacing s, the lattice moved
/// by `shift` in x and z; flag(x, index) decides each point's flag.
PointSet slab(const double s, const double shift,
              const std::function<std::uint8_t(const Vector3&, std::size_t)>& flag)
{
  PointSet set;
  const int n = static_cast<int>(std::lround(40e-3 / s)), ny = static_cast<int>(std::lround(4e-3 / s));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < n; ++i)
      {
        const Vector3 p(-20e-3 + (i + 0.5) * s + shift, (j + 0.5) * s, -20e-3 + (k + 0.5) * s + shift);
        set.x.push_back(p);
        set.volume.push_back(s * s * s);
        set.flags.push_back(flag(p, set.x.size()));
      }
  return set;
}

WoundGeometry shot(const double outline_grid)
{
  WoundGeometry g;
  g.box_lower = Vector3(-20e-3, 0.0, -20e-3);
  g.box_upper = Vector3(20e-3, 4e-3, 20e-3);
  g.path_origin = Vector3(0.0, -10e-3, 0.0);
  g.path_direction = Vector3::UnitY();
  g.cell_size = 1e-3;
  g.face_layer = 1e-3;
  g.outline_spacing = outline_grid;
  return g;
}

constexpr std::uint8_t debris = 3 | debris_bit;

std::function<std::uint8_t(const Vector3&, std::size_t)> ellipse(const double a, const double b)
{
  return [a, b](const Vector3& p, std::size_t) {
    return std::uint8_t((p[0] / a) * (p[0] / a) + (p[2] / b) * (p[2] / b) < 1.0 ? debris : 0);
  };
}
} // namespace

TEST(WoundOutline, ADiscOfDebrisGivesItsDiameter)
{
  const double radius = 4.5e-3;
  const PointSet set = slab(0.5e-3, 0.0, ellipse(radius, radius));
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, shot(1e-3));
  ASSERT_TRUE(m.entrance.outline.measured);
  ASSERT_TRUE(m.exit.outline.measured);
  // The half contour of a disc's indicator smoothed by a kernel narrower than the disc lies
  // within a few per cent of its edge (the edge's curvature shifts it inwards).
  EXPECT_NEAR(m.entrance.outline.equivalent_diameter, 2 * radius, 0.02 * 2 * radius);
  EXPECT_NEAR(m.entrance.outline.aspect_ratio, 1.0, 0.01);
  EXPECT_NEAR(m.exit.outline.equivalent_diameter, m.entrance.outline.equivalent_diameter, 1e-12);
  EXPECT_EQ(m.entrance.outline.grid_spacing, 1e-3);
}

TEST(WoundOutline, AnEllipseGivesItsAxesRatioAndAxis)
{
  const double a = 6e-3, b = 3e-3;
  const PointSet set = slab(0.5e-3, 0.0, ellipse(a, b));
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, shot(1e-3));
  ASSERT_TRUE(m.exit.outline.measured);
  EXPECT_NEAR(m.exit.outline.aspect_ratio, a / b, 0.03 * a / b);
  EXPECT_NEAR(std::abs(m.exit.outline.major_axis[0]), 1.0, 1e-6);
  EXPECT_NEAR(m.exit.outline.equivalent_diameter, 2 * std::sqrt(a * b), 0.03 * 2 * std::sqrt(a * b));
}

// The lattice of a 1 mm cell (0.5 mm) under an ellipse of 6 x 3.5 mm, and the same lattice
// moved by half a spacing in both directions of the face.
TEST(WoundOutline, AHalfSpacingShiftOfTheLatticeLeavesTheOutline)
{
  const double s = 0.5e-3, a = 6e-3, b = 3.5e-3;
  const PointSet here = slab(s, 0.0, ellipse(a, b));
  const PointSet shifted = slab(s, 0.5 * s, ellipse(a, b));
  const WoundMetrics m0 = compute_wound_metrics(here.x, here.volume, here.flags, shot(1e-3));
  const WoundMetrics m1 = compute_wound_metrics(shifted.x, shifted.volume, shifted.flags, shot(1e-3));
  ASSERT_TRUE(m0.exit.outline.measured && m1.exit.outline.measured);
  const FaceOutline &o0 = m0.exit.outline, &o1 = m1.exit.outline;
  // Measured: the outline's diameter moves -0.34 % and its aspect ratio -1.3 % (the points'
  // own: -0.58 % and -1.0 %); which points the ellipse holds changes with the lattice, and
  // no measure can recover what the sampling lost, so the bounds are those of the sampling.
  EXPECT_NEAR(o1.equivalent_diameter, o0.equivalent_diameter, 0.01 * o0.equivalent_diameter);
  EXPECT_NEAR(o1.aspect_ratio, o0.aspect_ratio, 0.02 * o0.aspect_ratio);
  EXPECT_NEAR(o0.aspect_ratio, a / b, 0.04 * a / b); // the kernel rounds the ends: -2.3 %
}

// Isolated failed points scattered around the wound (one in twenty out to twice its size, as
// a ragged failure front leaves them) pull the points' second moments outwards; alone in the
// smoothing kernel, each stays below one half and the outline ignores them.
TEST(WoundOutline, ScatteredFailedPointsAroundTheWoundDoNotMoveTheOutline)
{
  const double a = 6e-3, b = 3e-3;
  const PointSet clean = slab(0.5e-3, 0.0, ellipse(a, b));
  const PointSet ragged = slab(0.5e-3, 0.0, [&](const Vector3& p, const std::size_t index) {
    const double e = (p[0] / a) * (p[0] / a) + (p[2] / b) * (p[2] / b);
    return std::uint8_t(e < 1.0 || (e < 4.0 && index % 20 == 7) ? debris : 0);
  });
  const WoundMetrics m0 = compute_wound_metrics(clean.x, clean.volume, clean.flags, shot(1e-3));
  const WoundMetrics m1 = compute_wound_metrics(ragged.x, ragged.volume, ragged.flags, shot(1e-3));
  // Measured: the outline's diameter +1.8 % and aspect ratio +1.2 % (the scattered points
  // next to the edge lift it there); the points' own +7.1 % and -9.5 %.
  EXPECT_NEAR(m1.exit.outline.equivalent_diameter, m0.exit.outline.equivalent_diameter,
              0.03 * m0.exit.outline.equivalent_diameter);
  EXPECT_NEAR(m1.exit.outline.aspect_ratio, m0.exit.outline.aspect_ratio, 0.02 * m0.exit.outline.aspect_ratio);
  EXPECT_GT(std::abs(m1.exit.aspect_ratio / m0.exit.aspect_ratio - 1.0), 0.05)
    << "the scattered points should move the points' own measure, or the test checks nothing";
}

TEST(WoundOutline, NoGridOrNoDebrisGivesNoOutline)
{
  const PointSet set = slab(0.5e-3, 0.0, ellipse(4e-3, 4e-3));
  EXPECT_FALSE(compute_wound_metrics(set.x, set.volume, set.flags, shot(0.0)).exit.outline.measured);
  PointSet flags_only = set;
  for (std::uint8_t& f : flags_only.flags)
    f &= 3; // totally failed, but every point still carries deviatoric stress
  EXPECT_FALSE(compute_wound_metrics(flags_only.x, flags_only.volume, flags_only.flags, shot(1e-3))
                 .exit.outline.measured);
}
