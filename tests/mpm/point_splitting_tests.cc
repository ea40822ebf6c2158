// Point splitting (Grid/Point splitting, mpm/point_splitting.h): a stretched point becomes two
// halves along its longest edge with the body's mass, momentum, mass centre and energy
// unchanged; the domain follows the material; a run that splits conserves mass and momentum.
#include "mpm/point_splitting.h"
#include "mpm/solver.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace vulnus;
using namespace vulnus::mpm;

namespace
{
constexpr double h = 1e-3;

/// Points seeded 2 per cell axis at x, each with a plastic history, the first one's domain
/// stretched to `edge` (cells) along `direction` (its other edges as seeded).
Particles stretched_points(const std::vector<Vector3>& x, const double edge,
                           const Vector3& direction)
{
  Particles p;
  p.start_body();
  const double volume = std::pow(0.5 * h, 3);
  for (const Vector3& at : x)
    p.append(at, Vector3(1.0, -2.0, 3.0), 1030.0 * volume, volume, Vector3::UnitX(), true);
  p.finish_body();
  p.domain[0].col(0) = (0.5 * edge * h * direction.normalized()).cast<float>();
  p.deformation_gradient[0](0, 0) = edge / 0.5;
  p.stress[0] << 1, 2, 3, 4, 5, 6;
  p.energy_density[0] = 7.0;
  p.plastic_of(0)->equivalent_plastic_strain = 0.4;
  return p;
}

double total_mass(const Particles& p)
{
  double m = 0.0;
  for (const double mi : p.mass)
    m += mi;
  return m;
}
} // namespace

TEST(PointSplitting, AStretchedPointBecomesTwoHalvesAlongItsLongestEdge)
{
  const Vector3 direction = Vector3(1.0, 1.0, 0.0).normalized();
  Particles points = stretched_points({Vector3(0.01, 0.01, 0.01), Vector3(0.02, 0.01, 0.01)}, 0.9,
                                      direction);
  const double mass_before = total_mass(points);
  const Vector3 centre_before = points.mass[0] * points.position[0] +
                                points.mass[1] * points.position[1];
  const double energy_before = points.reference_volume[0] * points.energy_density[0];
  PointSplitting settings;
  settings.longest_edge = 0.75 * h;
  const Particles children = split_stretched_points(points, 0, points.size(), settings);
  // Only the stretched point splits; the other (0.5 cells) is below the limit.
  ASSERT_EQ(children.size(), 1u);
  const double quarter = 0.25 * 0.9 * h;
  EXPECT_NEAR((points.position[0] - Vector3(0.01, 0.01, 0.01) - quarter * direction).norm(), 0.0,
              1e-9);
  EXPECT_NEAR((children.position[0] - Vector3(0.01, 0.01, 0.01) + quarter * direction).norm(),
              0.0, 1e-9);
  EXPECT_NEAR(2.0 * children.domain[0].col(0).norm(), 0.45 * h, 1e-9);
  EXPECT_EQ(children.domain[0], points.domain[0]);
  // Mass, mass centre, momentum and stored energy are shared, not made.
  EXPECT_NEAR(total_mass(points) + children.mass[0], mass_before, 1e-15 * mass_before);
  const Vector3 centre_after = points.mass[0] * points.position[0] +
                               points.mass[1] * points.position[1] +
                               children.mass[0] * children.position[0];
  EXPECT_NEAR((centre_after - centre_before).norm(), 0.0, 1e-12 * centre_before.norm());
  EXPECT_EQ(children.velocity[0], points.velocity[0]);
  EXPECT_NEAR(points.reference_volume[0] * points.energy_density[0] +
                children.reference_volume[0] * children.energy_density[0],
              energy_before, 1e-12 * energy_before);
  // The state is the parent's, the history a copy of its own.
  EXPECT_EQ(children.deformation_gradient[0], points.deformation_gradient[0]);
  EXPECT_EQ(children.stress[0], points.stress[0]);
  ASSERT_NE(children.plastic_of(0), nullptr);
  EXPECT_EQ(children.plastic_of(0)->equivalent_plastic_strain, 0.4);
  EXPECT_NE(children.plastic_of(0), points.plastic_of(0));
  // Halved to 0.45 cells, neither splits again.
  EXPECT_EQ(split_stretched_points(points, 0, points.size(), settings).size(), 0u);
}

TEST(PointSplitting, DebrisAPlaneARigidBodyAndTheGridKeepAPointWhole)
{
  PointSplitting settings;
  settings.longest_edge = 0.75 * h;
  const auto splits = [&](Particles p) { return split_stretched_points(p, 0, p.size(), settings).size(); };
  const Vector3 x(0.3 * h, 0.01, 0.01);
  EXPECT_EQ(splits(stretched_points({x}, 1.5, Vector3::UnitX())), 1u);
  // Debris carries pressure alone: its domain measures nothing the grid should sample.
  Particles debris = stretched_points({x}, 1.5, Vector3::UnitX());
  debris.failure[0] = materials::total_failure;
  EXPECT_EQ(splits(debris), 0u);
  // A child 0.375 cells from the point, 0.3 cells from a mirror plane at x = 0, would cross it.
  SceneParameters scene = test::empty_scene(Vector3(0, 0, 0), Vector3(0.05, 0.05, 0.05), h);
  scene.domain_faces[0] = FaceCondition::symmetry;
  settings.planes = symmetry_planes(scene);
  EXPECT_EQ(splits(stretched_points({x}, 1.5, Vector3::UnitX())), 0u);
  EXPECT_EQ(splits(stretched_points({x}, 1.5, Vector3::UnitY())), 1u);
  // ... or land inside a rigid body, or outside the grid.
  settings.inside_rigid = [](const Vector3& at) { return at[1] < 0.01; };
  EXPECT_EQ(splits(stretched_points({x}, 1.5, Vector3::UnitY())), 0u);
  settings.inside_rigid = nullptr;
  settings.upper = Vector3(1.0, 0.0102, 1.0);
  EXPECT_EQ(splits(stretched_points({x}, 1.5, Vector3::UnitY())), 0u);
}

namespace
{
/// A rigid steel ball (radius 2.5 mm) at 80 m/s into a quarter of a gelatin-like block that
/// fails at a plastic strain of 2, 1 mm cells, 2 points per cell axis, mirror planes x = 0 and
/// z = 0; points split beyond `split_cells` (0: never).
SceneParameters ball_into_quarter_block(const double split_cells)
{
  SceneParameters scene = test::empty_scene(Vector3(0, -6e-3, 0), Vector3(10e-3, 12e-3, 10e-3), h);
  scene.domain_faces[0] = scene.domain_faces[4] = FaceCondition::symmetry;
  scene.materials.push_back(test::soft_gelatin("gel", 2.0));
  scene.materials.push_back(test::rigid_material("steel"));
  scene.bodies.push_back(test::box_body("block", "gel", Vector3(0, 0, 0), Vector3(10e-3, 10e-3, 10e-3),
                                        1030.0, 2));
  scene.bodies.push_back(test::steel_ball_projectile(Vector3(0, -2.6e-3, 0), 2.5e-3, 80.0));
  scene.contact.friction_coefficient = 0.0;
  scene.contact.exact_rigid_surface = true;
  scene.contact.hold_compressed_surfaces = true;
  scene.point_split_edge_cells = split_cells;
  scene.end_time = 1.5e-4;
  return scene;
}
} // namespace

TEST(PointSplitting, TheDomainFollowsTheMaterialAsFDoes)
{
  // Without volume averaging a point's domain is F times its seeded cube until it splits or
  // turns to debris (whose F keeps its volume alone). A limit of 100 cells tracks the domains
  // and splits nothing.
  Solver solver(ball_into_quarter_block(100.0));
  while (!solver.finished())
    solver.advance();
  const Particles& p = solver.points();
  std::size_t compared = 0, stretched = 0;
  for (std::size_t i = p.begin_of(0); i < p.end_of(0); ++i)
  {
    if (p.failure[i] == materials::total_failure)
      continue;
    const Tensor2 expected = p.deformation_gradient[i] * (0.25 * h);
    EXPECT_LT((p.domain[i].cast<double>() - expected).norm(), 1e-5 * expected.norm()) << i;
    ++compared;
    stretched += 2.0 * expected.colwise().norm().maxCoeff() > 0.6 * h;
  }
  EXPECT_GT(compared, 1000u);
  EXPECT_GT(stretched, 10u); // points the next test's limit would split
  EXPECT_EQ(solver.split_points(), 0u);
}

TEST(PointSplitting, ARunThatSplitsKeepsItsMassAndMomentumAndFreshIds)
{
  Solver solver(ball_into_quarter_block(0.6));
  const Vector3 initial_momentum = solver.initial_momentum();
  const double mass_before = solver.diagnostics().bodies[0].mass;
  const std::size_t n_before = solver.points().size();
  while (!solver.finished())
    solver.advance();
  const Particles& p = solver.points();
  const SceneDiagnostics d = solver.diagnostics();
  std::cout << solver.split_points() << " points split, " << p.size() << " points\n";
  EXPECT_GT(solver.split_points(), 10u);
  EXPECT_EQ(p.size(), n_before + solver.split_points() - solver.removed_points());
  EXPECT_NEAR(d.bodies[0].mass, mass_before, 1e-12 * mass_before);
  Vector3 supplied = Vector3::Zero();
  for (const Vector3& impulse : solver.support_impulses())
    supplied += impulse;
  EXPECT_LT((d.momentum - supplied - initial_momentum).norm() / initial_momentum.norm(), 1e-12);
  const std::set<std::uint32_t> ids(p.id.begin(), p.id.end());
  EXPECT_EQ(ids.size(), p.size());
  // What was not split is below the limit, debris, or held back by a plane or the ball.
  std::size_t above = 0;
  for (std::size_t i = p.begin_of(0); i < p.end_of(0); ++i)
    above += p.failure[i] != materials::total_failure &&
             2.0 * p.domain[i].colwise().norm().maxCoeff() > 0.6 * h;
  EXPECT_LT(above, solver.split_points() / 10 + 5);
}
