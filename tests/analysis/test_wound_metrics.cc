// Wound metrics on synthetic point sets with known answers: a circular cylinder of failed
// points (its diameter, aspect ratio 1), an elliptic cylinder (its axes ratio), a cone (area
// growing with depth), volumes by failure type, face wounds in a layer of fixed depth, and a
// slab whose box reads a little thick in single precision.
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

/// A 40 x 10 x 40 mm slab (y through the thickness) of points at spacing s; flag(x) decides.
PointSet slab(const double s, const std::function<std::uint8_t(const Vector3&)>& flag)
{
  PointSet set;
  for (double z = -20e-3 + s / 2; z < 20e-3; z += s)
    for (double y = s / 2; y < 10e-3; y += s)
      for (double x = -20e-3 + s / 2; x < 20e-3; x += s)
      {
        const Vector3 p(x, y, z);
        set.x.push_back(p);
        set.volume.push_back(s * s * s);
        set.flags.push_back(flag(p));
      }
  return set;
}

/// The slab's box, shot normally along +y from below through its centre.
WoundGeometry normal_shot()
{
  WoundGeometry g;
  g.box_lower = Vector3(-20e-3, 0.0, -20e-3);
  g.box_upper = Vector3(20e-3, 10e-3, 20e-3);
  g.path_origin = Vector3(0.0, -10e-3, 0.0);
  g.path_direction = Vector3::UnitY();
  g.cell_size = 1e-3;
  return g;
}
} // namespace

TEST(WoundMetrics, CircularCylinderGivesItsDiameterAndAspectRatioOne)
{
  const double radius = 4.5e-3, s = 0.25e-3;
  const PointSet set = slab(s, [&](const Vector3& p) {
    return std::uint8_t(p[0] * p[0] + p[2] * p[2] < radius * radius ? 3 : 0);
  });
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, normal_shot());
  // Staircase of a circle on a 0.25 mm lattice: area error ~ perimeter * s / 2 / area ~ 3%,
  // half that in the diameter.
  EXPECT_NEAR(m.entrance.equivalent_diameter, 2 * radius, 0.02 * 2 * radius);
  EXPECT_NEAR(m.exit.equivalent_diameter, 2 * radius, 0.02 * 2 * radius);
  EXPECT_NEAR(m.entrance.aspect_ratio, 1.0, 0.01);
  EXPECT_NEAR(m.exit.aspect_ratio, 1.0, 0.01);
  for (const double area : m.tract_area)
    EXPECT_NEAR(area, M_PI * radius * radius, 0.03 * M_PI * radius * radius);
  EXPECT_EQ(m.tract_area.size(), 10u);
}

TEST(WoundMetrics, EllipticCylinderGivesItsAxesRatio)
{
  const double a = 6e-3, b = 3e-3, s = 0.25e-3; // semi-axes along x and z
  const PointSet set = slab(s, [&](const Vector3& p) {
    return std::uint8_t((p[0] / a) * (p[0] / a) + (p[2] / b) * (p[2] / b) < 1.0 ? 3 : 0);
  });
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, normal_shot());
  // Second moments of an elliptic disc: a^2/4 and b^2/4, so the ratio of axes is a / b.
  EXPECT_NEAR(m.exit.aspect_ratio, a / b, 0.03 * a / b);
  EXPECT_NEAR(std::abs(m.exit.major_axis[0]), 1.0, 1e-6);
  EXPECT_NEAR(m.exit.equivalent_diameter, 2 * std::sqrt(a * b), 0.02 * 2 * std::sqrt(a * b));
}

TEST(WoundMetrics, ConeAreaGrowsWithDepth)
{
  const double s = 0.25e-3;
  auto radius_at = [](const double depth) { return 2e-3 + 0.4 * depth; }; // 2 mm -> 6 mm
  const PointSet set = slab(s, [&](const Vector3& p) {
    const double r = radius_at(p[1]);
    return std::uint8_t(p[0] * p[0] + p[2] * p[2] < r * r ? 3 : 0);
  });
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, normal_shot());
  ASSERT_EQ(m.tract_area.size(), 10u);
  for (std::size_t k = 0; k < m.tract_area.size(); ++k)
  {
    // Mean of pi r(y)^2 over the slice, r linear in y.
    const double y0 = k * 1e-3, y1 = y0 + 1e-3;
    const double r0 = radius_at(y0), r1 = radius_at(y1);
    const double expected = M_PI * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0;
    EXPECT_NEAR(m.tract_area[k], expected, 0.05 * expected) << "slice " << k;
    if (k > 0)
    {
      EXPECT_GT(m.tract_area[k], m.tract_area[k - 1]);
    }
  }
  EXPECT_LT(m.entrance.equivalent_diameter, m.exit.equivalent_diameter);
}

TEST(WoundMetrics, VolumesAndCountsByFailureType)
{
  PointSet set;
  const std::uint8_t flags[] = {0, 1, 1, 2, 3, 3, 3};
  for (std::size_t i = 0; i < 7; ++i)
  {
    set.x.push_back(Vector3(0, 5e-3, 0));
    set.volume.push_back(1e-9 * (i + 1));
    set.flags.push_back(flags[i]);
  }
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, normal_shot());
  EXPECT_EQ(m.counts[0], 1u);
  EXPECT_EQ(m.counts[1], 2u);
  EXPECT_EQ(m.counts[2], 1u);
  EXPECT_EQ(m.counts[3], 3u);
  EXPECT_NEAR(m.volumes[1], 5e-9, 1e-20);
  EXPECT_NEAR(m.volumes[3], 18e-9, 1e-20);
  EXPECT_EQ(m.entrance.n_points, 0u); // depth 5 mm: in neither face layer
  EXPECT_EQ(m.exit.n_points, 0u);
}

TEST(WoundMetrics, PathThroughBoxFindsTheFacesItCrosses)
{
  const Vector3 lower(-20e-3, 0.0, -20e-3), upper(20e-3, 10e-3, 20e-3);
  const PathThroughBox normal = path_through_box(lower, upper, Vector3(0, -5e-3, 0), Vector3::UnitY());
  ASSERT_TRUE(normal.hits);
  EXPECT_EQ(normal.entrance_face, 2);
  EXPECT_EQ(normal.exit_face, 3);
  EXPECT_NEAR(normal.length(), 10e-3, 1e-15);
  // Backwards along -y from above: enters y+, leaves y-.
  const PathThroughBox back = path_through_box(lower, upper, Vector3(0, 15e-3, 0), -Vector3::UnitY());
  EXPECT_EQ(back.entrance_face, 3);
  EXPECT_EQ(back.exit_face, 2);
  // Grazing along x through the slab's middle: enters x-, leaves x+ after 40 mm.
  const PathThroughBox side = path_through_box(lower, upper, Vector3(-30e-3, 5e-3, 0), Vector3::UnitX());
  EXPECT_EQ(side.entrance_face, 0);
  EXPECT_EQ(side.exit_face, 1);
  EXPECT_NEAR(side.length(), 40e-3, 1e-15);
  // Steep enough to leave through a side face: 80 degrees from y, from the centre of y-.
  const double a = 80.0 * M_PI / 180.0;
  const PathThroughBox steep =
    path_through_box(lower, upper, Vector3(0, 0, 0), Vector3(std::sin(a), std::cos(a), 0));
  // y+ would be reached at x = 10 mm tan 80 degrees = 56.7 mm: it leaves through x+ first.
  EXPECT_EQ(steep.entrance_face, 2);
  EXPECT_EQ(steep.exit_face, 1);
  EXPECT_NEAR(steep.length(), 20e-3 / std::sin(a), 1e-12);
  // A path that passes beside the box misses it.
  EXPECT_FALSE(path_through_box(lower, upper, Vector3(30e-3, -5e-3, 0), Vector3::UnitY()).hits);
}

// A 30 degree shot: a failed cylinder of radius r along the oblique path. Its wound on each
// face is an ellipse of area pi r^2 / cos 30 and axes ratio 1 / cos 30, the tract runs the
// path's length through the slab, 10 mm / cos 30, and a slice normal to the path that lies
// inside the slab cuts the cylinder's cross-section pi r^2.
TEST(WoundMetrics, ObliqueShotIsMeasuredOnTheFacesItCrosses)
{
  const double radius = 3e-3, s = 0.25e-3, angle = 30.0 * M_PI / 180.0;
  const Vector3 direction(std::sin(angle), std::cos(angle), 0.0);
  const Vector3 entry(-2e-3, 0.0, 0.0);
  const PointSet set = slab(s, [&](const Vector3& p) {
    const Vector3 r = p - entry;
    return std::uint8_t((r - r.dot(direction) * direction).squaredNorm() < radius * radius ? 3 : 0);
  });
  WoundGeometry g = normal_shot();
  g.path_origin = entry - 10e-3 * direction;
  g.path_direction = direction;
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, g);
  EXPECT_EQ(m.entrance.face, 2);
  EXPECT_EQ(m.exit.face, 3);
  const double ellipse = M_PI * radius * radius / std::cos(angle);
  // The face layer is a cell thick, so the ellipse is smeared by a cell along x (tan 30 of
  // it): about 2 % in the area and 8 % in the ratio on top of the lattice's staircase.
  EXPECT_NEAR(m.entrance.area, ellipse, 0.05 * ellipse);
  EXPECT_NEAR(m.exit.area, ellipse, 0.05 * ellipse);
  EXPECT_NEAR(m.entrance.aspect_ratio, 1.0 / std::cos(angle), 0.1);
  EXPECT_NEAR(std::abs(m.entrance.major_axis[0]), 1.0, 1e-6);
  EXPECT_NEAR(m.path.length(), 10e-3 / std::cos(angle), 1e-12);
  ASSERT_EQ(m.tract_area.size(), 12u); // ceil(11.55 mm / 1 mm)
  EXPECT_NEAR(m.tract_depth.back(), 11.5e-3, 1e-12);
  // Slices 4 to 7 (4-8 mm along the path) hold a whole cross-section inside the slab.
  for (std::size_t k = 4; k < 8; ++k)
    EXPECT_NEAR(m.tract_area[k], M_PI * radius * radius, 0.04 * M_PI * radius * radius) << k;
}

TEST(WoundMetrics, NoExitWoundForAProjectileThatDidNotLeave)
{
  const double radius = 4.5e-3, s = 0.5e-3;
  const PointSet set = slab(s, [&](const Vector3& p) {
    return std::uint8_t(p[0] * p[0] + p[2] * p[2] < radius * radius ? 3 : 0);
  });
  WoundGeometry g = normal_shot();
  g.projectile_exited = false;
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, g);
  EXPECT_EQ(m.entrance.face, 2);
  EXPECT_GT(m.entrance.n_points, 0u);
  EXPECT_EQ(m.exit.face, -1);
  EXPECT_EQ(m.exit.n_points, 0u);
  // A path beside the target crosses no face: no wound on any, no tract.
  g.path_origin = Vector3(30e-3, -10e-3, 0.0);
  const WoundMetrics beside = compute_wound_metrics(set.x, set.volume, set.flags, g);
  EXPECT_EQ(beside.entrance.face, -1);
  EXPECT_TRUE(beside.tract_area.empty());
  EXPECT_EQ(beside.counts[3], m.counts[3]);
}

// The face wounds are measured in a layer of fixed depth, not one cell: a wound that flares
// at the exit face (an elliptic slot in the last 0.5 mm over a circular tract) reads the same
// on a 1 mm and a 0.5 mm grid when the layer is 1 mm, and differently when it is one cell.
TEST(WoundMetrics, FaceLayerOfFixedDepthMeasuresTheSameWoundOnEveryGrid)
{
  const double s = 0.125e-3, radius = 3e-3;
  const PointSet set = slab(s, [&](const Vector3& p) {
    const bool slot = p[1] > 9.5e-3 && std::abs(p[0]) < 8e-3 && std::abs(p[2]) < 2e-3;
    return std::uint8_t(slot || p[0] * p[0] + p[2] * p[2] < radius * radius ? 3 : 0);
  });
  auto exit_of = [&](const double cell, const double layer) {
    WoundGeometry g = normal_shot();
    g.cell_size = cell;
    g.face_layer = layer;
    return compute_wound_metrics(set.x, set.volume, set.flags, g).exit;
  };
  const FaceWound one_cell_coarse = exit_of(1e-3, 0.0), one_cell_fine = exit_of(0.5e-3, 0.0);
  const FaceWound fixed_coarse = exit_of(1e-3, 1e-3), fixed_fine = exit_of(0.5e-3, 1e-3);
  // The one-cell layer of the fine grid is all slot; the coarse one is half slot, half tract.
  EXPECT_GT(one_cell_fine.aspect_ratio, 1.2 * one_cell_coarse.aspect_ratio);
  EXPECT_DOUBLE_EQ(fixed_fine.aspect_ratio, fixed_coarse.aspect_ratio);
  EXPECT_DOUBLE_EQ(fixed_fine.area, fixed_coarse.area);
  EXPECT_DOUBLE_EQ(fixed_coarse.aspect_ratio, one_cell_coarse.aspect_ratio);
  // Area: the mean failed cross-section over the layer. The slot and the circle's two caps
  // beyond |z| = 2 mm in the last 0.5 mm, the circle alone below.
  const double d = 2e-3, cap = radius * radius * std::acos(d / radius) -
                               d * std::sqrt(radius * radius - d * d);
  const double slot_and_caps = 16e-3 * 4e-3 + 2 * cap, tract = M_PI * radius * radius;
  EXPECT_NEAR(one_cell_fine.area, slot_and_caps, 0.03 * slot_and_caps);
  EXPECT_NEAR(fixed_coarse.area, 0.5 * (slot_and_caps + tract), 0.03 * slot_and_caps);
}

TEST(WoundMetrics, DebrisIsEveryFailedPointWithoutDeviatoricStressWhateverItsFlag)
{
  // A totally failed core of radius 3 mm in a matrix-failed ring out to 5 mm; the ring's
  // points at x > 0 carry no deviatoric stress (their fibres are not stretched).
  const double core = 3e-3, ring = 5e-3, s = 0.25e-3;
  const PointSet set = slab(s, [&](const Vector3& p) {
    const double r2 = p[0] * p[0] + p[2] * p[2];
    if (r2 < core * core)
      return std::uint8_t(3 | debris_bit);
    if (r2 < ring * ring)
      return std::uint8_t(p[0] > 0.0 ? 1 | debris_bit : 1);
    return std::uint8_t(0);
  });
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, normal_shot());
  const double core_area = M_PI * core * core;
  const double debris_area = core_area + 0.5 * M_PI * (ring * ring - core * core);
  EXPECT_NEAR(m.volumes[3], core_area * 10e-3, 0.03 * core_area * 10e-3);
  EXPECT_NEAR(m.volumes[1], 2.0 * (debris_area - core_area) * 10e-3,
              0.03 * (debris_area - core_area) * 10e-3);
  EXPECT_NEAR(m.debris_volume, debris_area * 10e-3, 0.03 * debris_area * 10e-3);
  // Half the ring's points, to the few the float lattice puts on either side of x = 0.
  EXPECT_NEAR(double(m.debris_count), m.counts[3] + 0.5 * m.counts[1], 0.01 * m.counts[1]);
  ASSERT_EQ(m.debris_tract_area.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k)
  {
    EXPECT_NEAR(m.tract_area[k], core_area, 0.03 * core_area) << "slice " << k;
    EXPECT_NEAR(m.debris_tract_area[k], debris_area, 0.03 * debris_area) << "slice " << k;
  }
  // The face wounds stay those of the total flag.
  EXPECT_NEAR(m.entrance.equivalent_diameter, 2 * core, 0.02 * 2 * core);
}

TEST(WoundMetrics, DebrisMeansNoDeviatoricStressToRounding)
{
  Eigen::Matrix<double, 6, 1> stress;
  stress << -3e5, -3e5, -3e5, 0, 0, 0; // pressure alone
  EXPECT_TRUE(carries_no_deviatoric_stress(stress));
  stress << -1.0 / 3.0, -1.0 / 3.0, -1.0 / 3.0, 0, 0, 0; // not exact in binary
  EXPECT_TRUE(carries_no_deviatoric_stress(stress));
  EXPECT_TRUE(carries_no_deviatoric_stress(Eigen::Matrix<double, 6, 1>::Zero()));
  // A fibre tension of a millionth of the pressure along x, then a shear of that size.
  stress << -3e5 + 0.3, -3e5, -3e5, 0, 0, 0;
  EXPECT_FALSE(carries_no_deviatoric_stress(stress));
  stress << -3e5, -3e5, -3e5, 0, 0.3, 0;
  EXPECT_FALSE(carries_no_deviatoric_stress(stress));
}

// The run's target box comes from single-precision reference positions: a 10 mm slab can read
// 10.0000002 mm. That must not add an empty slice, which would lower the tract's mean area by
// a cell-dependent share (1/11 at 1 mm).
TEST(WoundMetrics, ASlabReadInSinglePrecisionHasNoEmptyLastSlice)
{
  const double radius = 3e-3, s = 0.5e-3;
  const PointSet set = slab(s, [&](const Vector3& p) {
    return std::uint8_t(p[0] * p[0] + p[2] * p[2] < radius * radius ? 3 : 0);
  });
  WoundGeometry g = normal_shot();
  g.box_upper[1] = 10e-3 + 2e-10; // as the coarse water slab read
  ASSERT_GT(g.box_upper[1], 10e-3);
  const WoundMetrics m = compute_wound_metrics(set.x, set.volume, set.flags, g);
  ASSERT_EQ(m.tract_area.size(), 10u);
  double total = 0.0;
  for (std::size_t p = 0; p < set.x.size(); ++p)
    total += set.flags[p] == 3 ? set.volume[p] : 0.0;
  double mean = 0.0;
  for (const double area : m.tract_area)
    mean += area / m.tract_area.size();
  EXPECT_NEAR(mean, total / 10e-3, 1e-9 * total / 10e-3);
}
