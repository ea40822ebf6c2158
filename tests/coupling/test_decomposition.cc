// The MPM/FE split: what goes where, the checks that refuse an impossible split, and where a
// zone ends along the bullet's path.
#include "coupling/hybrid_solver.h"
#include "hybrid_test_scenes.h"

#include <gtest/gtest.h>

namespace vulnus::coupling
{
namespace
{
using testing::block_scene;
using testing::uniform_far_field;
using testing::zone;

std::string all_problems(const mpm::SceneParameters& s, const HybridParameters& h)
{
  std::string text;
  for (const ParameterProblem& p : check_decomposition(s, h, uniform_far_field(1e-3)))
    text += describe(p) + "\n";
  return text;
}

/// A slab [-w, w] x [0, 10 mm] x [-w, w] and the paper's bullet (radius 4.5 mm) flying along +y
/// through its centre.
mpm::SceneParameters slab_and_bullet(const double w)
{
  mpm::SceneParameters s = block_scene({-w, -0.02, -w}, {w, 0.035, w}, 1e-3);
  s.bodies[0].box_min = {-w, 0.0, -w};
  s.bodies[0].box_max = {w, 0.01, w};
  mpm::BodyParameters bullet;
  bullet.name = "bullet";
  bullet.material = "tissue";
  bullet.shape = mpm::BodyShape::cylinder;
  bullet.center = {0.0, -0.016, 0.0};
  bullet.radius = 0.0045;
  bullet.length = 0.015;
  bullet.initial_velocity = {0.0, 150.0, 0.0};
  bullet.is_projectile = true;
  s.bodies.push_back(bullet);
  return s;
}

TEST(Decomposition, SplitsTheBodyIntoZoneAndFarField)
{
  mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, 1e-3);
  s.domain_faces[0] = mpm::FaceCondition::fixed;
  s.domain_faces[3] = mpm::FaceCondition::roller;
  const HybridScene split = decompose(s, zone({0.004, 0.004, 0.004}, {0.008, 0.008, 0.008},
                                              CouplingScheme::same_step),
                                      uniform_far_field(1e-3));
  EXPECT_NEAR(split.mpm.bodies[0].box_min[0], 0.004, 1e-15);
  EXPECT_NEAR(split.mpm.bodies[0].box_max[2], 0.008, 1e-15);
  EXPECT_TRUE(split.fe.has_hole);
  EXPECT_NEAR(split.fe.slab_max[1], 0.012, 1e-15);
  EXPECT_NEAR(split.fe.hole_min[1], 0.004, 1e-15);
  EXPECT_EQ(split.fe.faces[0].condition, fem::FaceParameters::Condition::fixed);
  EXPECT_EQ(split.fe.faces[3].condition, fem::FaceParameters::Condition::roller);
  EXPECT_EQ(split.fe.faces[1].condition, fem::FaceParameters::Condition::free);
  EXPECT_TRUE(split.fe.staggered_velocity);
  EXPECT_EQ(split.fe.interface_condition, fem::InterfaceCondition::velocity_driven);

  // Every node on the surface of the 4 x 4 x 4 cell zone is shared: 5^3 - 3^3.
  HybridSolver solver(split, MPI_COMM_WORLD);
  EXPECT_EQ(solver.n_interface_nodes(), 125u - 27u);
}

// Zone = around path: the paper's bullet (radius 4.5 mm, along +y through a 10 mm slab) with a
// 1.5 mm margin gives radius + one cell + margin = 7 mm on either side of the axis, through the
// whole thickness; a margin off the grid widens to the next node.
TEST(Decomposition, ZoneAroundThePathHoldsTheBulletRadiusCellAndMargin)
{
  const mpm::SceneParameters s = slab_and_bullet(0.025);
  HybridParameters hybrid = zone({0, 0, 0}, {0, 0, 0}, CouplingScheme::multi_step);
  hybrid.zone_start = ZoneStart::around_path;
  hybrid.path_margin = 0.0015;
  HybridParameters resolved = resolve_zone(s, hybrid);
  for (int d : {0, 2})
  {
    EXPECT_NEAR(resolved.zone_min[d], -0.007, 1e-12);
    EXPECT_NEAR(resolved.zone_max[d], 0.007, 1e-12);
  }
  EXPECT_NEAR(resolved.zone_min[1], 0.0, 1e-12);
  EXPECT_NEAR(resolved.zone_max[1], 0.01, 1e-12);
  hybrid.path_margin = 0.0012;
  resolved = resolve_zone(s, hybrid);
  EXPECT_NEAR(resolved.zone_max[0], 0.007, 1e-12);
  EXPECT_TRUE(check_decomposition(s, hybrid, uniform_far_field(1e-3)).empty());

  // The adaptive zone's limit: the reach in whole cells, cut at the body's faces.
  hybrid.adaptive.enabled = true;
  hybrid.adaptive.reach = 0.0205;
  const HybridScene split = decompose(s, hybrid, uniform_far_field(1e-3));
  EXPECT_NEAR(split.limit_min[0], -0.025, 1e-12); // 7 + 21 cells would leave the body
  EXPECT_NEAR(split.limit_max[2], 0.025, 1e-12);
  EXPECT_NEAR(split.limit_max[1], 0.01, 1e-12);
  EXPECT_TRUE(split.fe.has_focus && split.fe.track_failure_proximity);
  hybrid.adaptive.reach = 0.0005;
  EXPECT_NE(all_problems(s, hybrid).find("below one grid cell"), std::string::npos);
}

TEST(Decomposition, RefusesAZoneOffTheGridNodes)
{
  const mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, 1e-3);
  const std::string text =
    all_problems(s, zone({0.0045, 0.004, 0.004}, {0.008, 0.008, 0.008}, CouplingScheme::same_step));
  EXPECT_NE(text.find("x = 0.0045 m is not on a grid node"), std::string::npos) << text;
  // The node suggested lies outwards, so the zone does not shrink (an inward suggestion
  // could be refused as too small for the projectile).
  EXPECT_NE(text.find("move it to 0.004 m"), std::string::npos) << text;
  const std::string upper =
    all_problems(s, zone({0.004, 0.004, 0.004}, {0.0075, 0.008, 0.008}, CouplingScheme::same_step));
  EXPECT_NE(upper.find("x = 0.0075 m is not on a grid node"), std::string::npos) << upper;
  EXPECT_NE(upper.find("move it to 0.008 m"), std::string::npos) << upper;
}

TEST(Decomposition, RefusesAZoneOutsideTheBodyOrCoveringIt)
{
  const mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, 1e-3);
  EXPECT_NE(all_problems(s, zone({0.004, 0.004, 0.004}, {0.008, 0.008, 0.014},
                                 CouplingScheme::same_step))
              .find("must lie inside body 'block'"),
            std::string::npos);
  EXPECT_NE(all_problems(s, zone({0, 0, 0}, {0.012, 0.012, 0.012}, CouplingScheme::same_step))
              .find("leaving no far field"),
            std::string::npos);
}

TEST(Decomposition, RefusesAnImplicitFarFieldWithTheSameStepScheme)
{
  const mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, 1e-3);
  fem::FeSceneParameters f = uniform_far_field(1e-3);
  f.integrator = fem::TimeIntegrator::newmark;
  const auto problems = check_decomposition(
    s, zone({0.004, 0.004, 0.004}, {0.008, 0.008, 0.008}, CouplingScheme::same_step), f);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].parameters, (std::vector<std::string>{"scheme", "far_field.integrator"}));
  EXPECT_NE(problems[0].remedy.find("multi-step scheme"), std::string::npos);
}

TEST(Decomposition, RefusesAZoneThatMissesTheBulletPath)
{
  const mpm::SceneParameters s = slab_and_bullet(0.02);
  // 4.5 mm radius plus one cell needs |x|, |z| >= 5.5 mm of zone around the axis.
  EXPECT_EQ(all_problems(s, zone({-0.006, 0.0, -0.006}, {0.006, 0.01, 0.006},
                                 CouplingScheme::same_step)),
            "");
  const std::string text =
    all_problems(s, zone({-0.005, 0.0, -0.006}, {0.006, 0.01, 0.006}, CouplingScheme::same_step));
  EXPECT_NE(text.find("path of projectile 'bullet'"), std::string::npos) << text;
  EXPECT_NE(text.find("zone's x bounds"), std::string::npos) << text;
}

// A zone may end along the path inside the slab, in the direction of flight: the paper's bullet
// (a 15 mm cylinder along +y, its front at y = -1 mm at the start) into the 10 mm slab, the
// zone to y = 6 mm. Its end is reported; the zone must still hold the path sideways and from
// the slab's face, and end more than two cells beyond that face and the bullet's front.
TEST(Decomposition, AZoneMayEndAlongThePathInTheDirectionOfFlight)
{
  const mpm::SceneParameters s = slab_and_bullet(0.02);
  const auto box = [](const double y_min, const double x_min, const double y_max) {
    return zone({x_min, y_min, -0.006}, {0.006, y_max, 0.006}, CouplingScheme::same_step);
  };
  EXPECT_EQ(all_problems(s, box(0.0, -0.006, 0.006)), "");
  const ZoneEnd end = zone_end_along_path(s, box(0.0, -0.006, 0.006));
  ASSERT_TRUE(end.ends);
  EXPECT_EQ(end.axis, 1);
  EXPECT_TRUE(end.upper);
  EXPECT_NEAR(end.coordinate, 0.006, 1e-15);
  EXPECT_NEAR(end.distance, 0.022, 1e-12); // from the bullet's tail at y = -16 mm
  EXPECT_NEAR(end.body_entry, 0.016, 1e-12);
  EXPECT_TRUE(end.passed_by({0.0, 0.0061, 0.0}));
  EXPECT_FALSE(end.passed_by({0.0, 0.0059, 0.0}));
  EXPECT_FALSE(zone_end_along_path(s, box(0.0, -0.006, 0.01)).ends); // to the far face

  // Within two cells of the slab's face: the run would stop at once.
  const auto early = check_decomposition(s, box(0.0, -0.006, 0.001), uniform_far_field(1e-3));
  ASSERT_EQ(early.size(), 1u);
  EXPECT_EQ(early[0].parameters, std::vector<std::string>{"zone_max"});
  EXPECT_NE(early[0].problem.find("the zone ends at y = 0.001 m along the path of projectile "
                                  "'bullet', within 2 cells of where the path enters body "
                                  "'block'"),
            std::string::npos)
    << early[0].problem;
  // Too close sideways, or starting behind the slab's face: refused as before.
  EXPECT_NE(all_problems(s, box(0.0, -0.005, 0.006)).find("zone's x bounds"), std::string::npos);
  EXPECT_NE(all_problems(s, box(0.002, -0.006, 0.006)).find("zone's y bounds"),
            std::string::npos);

  // A projectile that starts inside the slab, beyond the zone's end: refused.
  mpm::SceneParameters inside = s;
  inside.bodies[1].shape = mpm::BodyShape::sphere;
  inside.bodies[1].radius = 0.002;
  inside.bodies[1].center = {0.0, 0.005, 0.0};
  const std::string behind = all_problems(inside, box(0.0, -0.006, 0.004));
  EXPECT_NE(behind.find("within 2 cells of the projectile's front at its start"),
            std::string::npos)
    << behind;

  // A split scene's zone as an adaptive zone grows it: the end moves, and goes at the far face.
  HybridParameters adaptive = box(0.0, -0.006, 0.006);
  adaptive.adaptive.enabled = true;
  const HybridScene split = decompose(s, adaptive, uniform_far_field(1e-3));
  EXPECT_NEAR(zone_end_along_path(split, split.hybrid.zone_min, split.hybrid.zone_max).coordinate,
              0.006, 1e-15);
  std::array<double, 3> grown = split.hybrid.zone_max;
  grown[1] = 0.008;
  EXPECT_NEAR(zone_end_along_path(split, split.hybrid.zone_min, grown).coordinate, 0.008, 1e-15);
  grown[1] = 0.01;
  EXPECT_FALSE(zone_end_along_path(split, split.hybrid.zone_min, grown).ends);
}
} // namespace
} // namespace vulnus::coupling
