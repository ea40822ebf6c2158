// Graded grids (mpm/grid_axis.h): the axis layout, the linear tents' reproduction of constants
// and of x on uneven cells, the points laid per graded cell, and a ball shot into a gel
// cylinder on a graded plane against the same scene on the uniform grid.
#include "mpm/body_builder.h"
#include "mpm/solver.h"
#include "mpm/stencil.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace vulnus;
using namespace vulnus::mpm;

namespace
{
constexpr double h = 1e-3;

GridGrading grading(const Vector3& fine_min, const Vector3& fine_max, const double largest,
                    const double growth_length)
{
  GridGrading g;
  g.largest_cells = largest;
  g.growth_length = growth_length;
  for (int d = 0; d < 3; ++d)
  {
    g.fine_min[d] = fine_min[d];
    g.fine_max[d] = fine_max[d];
  }
  return g;
}
} // namespace

TEST(GradedGrid, AnAxisHasFineCellsInItsBoxAndCellsThatGrowToTheLargestOutside)
{
  const GridAxis axis(-20e-3, 30e-3, h, -3e-3, 5e-3, 2e-3, 6.0, Grid::padding);
  // The ends are the domain's faces.
  EXPECT_EQ(axis.node(0), -20e-3);
  EXPECT_EQ(axis.upper(), 30e-3);
  int fine = 0;
  for (int i = 0; i < axis.cells(); ++i)
  {
    const double mid = 0.5 * (axis.node(i) + axis.node(i + 1));
    EXPECT_NEAR(axis.width(i), axis.node(i + 1) - axis.node(i), 1e-15);
    EXPECT_GE(axis.width(i), h * (1 - 1e-12)) << i;
    EXPECT_LE(axis.width(i), 1.5 * 6.0 * h) << i;
    if (mid > -3e-3 && mid < 5e-3)
    {
      EXPECT_NEAR(axis.width(i), h, 1e-15) << i;
      ++fine;
    }
    // Away from the box the cells do not shrink, but for the end cell, which is widened or cut
    // to end on the face.
    if (mid > 5e-3 && i + 2 < axis.cells())
    {
      EXPECT_GE(axis.width(i + 1), axis.width(i) * (1 - 1e-12)) << i;
    }
    if (mid < -3e-3 && i > 1)
    {
      EXPECT_GE(axis.width(i - 1), axis.width(i) * (1 - 1e-12)) << i;
    }
    // The map to cell units puts a node on its index and a cell's middle half-way.
    EXPECT_NEAR(axis.to_cell_units(axis.node(i)), i, 1e-9) << i;
    EXPECT_NEAR(axis.to_cell_units(mid), i + 0.5, 1e-9) << i;
  }
  EXPECT_EQ(fine, 8);
  // The widest cell is the largest allowed, reached within the 25 mm past the box.
  double widest = 0.0;
  for (int i = 0; i < axis.cells(); ++i)
    widest = std::max(widest, axis.width(i));
  EXPECT_GE(widest, 6.0 * h * (1 - 1e-12));
  // Far fewer cells than the 50 a uniform grid takes.
  EXPECT_LT(axis.cells(), 30);
}

TEST(GradedGrid, AFineBoxAtOrPastTheEndsStretchesItsEndCellsAndNoCellIsNarrowerThanACell)
{
  // The box starts half a cell above the lower end and reaches past the upper one.
  const GridAxis axis(0.0, 10.3e-3, h, 0.5e-3, 12e-3, 2e-3, 4.0, Grid::padding);
  EXPECT_EQ(axis.node(0), 0.0);
  EXPECT_EQ(axis.upper(), 10.3e-3);
  EXPECT_EQ(axis.cells(), 10);
  for (int i = 0; i < axis.cells(); ++i)
    EXPECT_NEAR(axis.width(i), i < 9 ? h : 1.3e-3, 1e-15) << i;
  // Padding cells beyond the ends are as wide as the end cells.
  EXPECT_NEAR(axis.node(-2), -2 * h, 1e-15);
  EXPECT_NEAR(axis.node(12), 10.3e-3 + 2 * 1.3e-3, 1e-15);
  // A box ending 0.3 cells short of the upper end leaves no sliver: its last cell is widened.
  const GridAxis short_of_end(0.0, 10.3e-3, h, 0.0, 10e-3, 2e-3, 4.0, Grid::padding);
  EXPECT_EQ(short_of_end.cells(), 10);
  for (int i = 0; i < short_of_end.cells(); ++i)
    EXPECT_GE(short_of_end.width(i), h * (1 - 1e-12)) << i;
}

TEST(GradedGrid, EveryCoordinateIsLocatedInTheCellWhoseNodesBracketIt)
{
  // Fine cells (found by division) and graded ones (found by the table) alike, at random
  // coordinates, on every node and a rounding's width either side of it, and in the padding.
  const GridAxis axis(-20e-3, 30e-3, h, -3.3e-3, 5.2e-3, 0.5e-3, 8.0, Grid::padding);
  std::vector<double> xs;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> anywhere(axis.node(-Grid::padding),
                                                  axis.node(axis.cells() + Grid::padding));
  for (int n = 0; n < 20000; ++n)
    xs.push_back(anywhere(random));
  for (int i = -Grid::padding; i <= axis.cells() + Grid::padding; ++i)
    for (const double x : {axis.node(i), std::nextafter(axis.node(i), -1.0),
                           std::nextafter(axis.node(i), 1.0)})
      xs.push_back(x);
  for (const double x : xs)
  {
    int holding = -Grid::padding;
    while (holding + 1 < axis.cells() + Grid::padding && axis.node(holding + 1) <= x)
      ++holding;
    double width = 0.0, inverse_width = 0.0;
    const double s = axis.locate(x, width, inverse_width);
    EXPECT_EQ(width, axis.width(holding)) << x;
    EXPECT_EQ(inverse_width, axis.inverse_width(holding)) << x;
    EXPECT_EQ(s, holding + (x - axis.node(holding)) * axis.inverse_width(holding)) << x;
    EXPECT_EQ(axis.to_cell_units(x), s) << x;
  }
}

TEST(GradedGrid, LinearTentsOnUnevenCellsReproduceConstantsAndPositions)
{
  const Grid grid(Vector3(-10e-3, -10e-3, -10e-3), Vector3(12e-3, 12e-3, 12e-3), h, false,
                  grading(Vector3(-2e-3, -1e-3, 0), Vector3(2e-3, 3e-3, 1e-3), 5.0, 1.5e-3));
  ASSERT_TRUE(grid.graded());
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-9e-3, 11e-3);
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  for (int trial = 0; trial < 300; ++trial)
  {
    const Vector3 x(coordinate(random), coordinate(random), coordinate(random));
    double sum = 0.0;
    Vector3 gradient_sum = Vector3::Zero(), position_sum = Vector3::Zero();
    Eigen::Matrix3d gradient_of_position = Eigen::Matrix3d::Zero();
    Vector3 offset_error = Vector3::Zero();
    for_each_node<ShapeFunction::linear>(
      grid, 0.0, x, F,
      [&](std::int64_t key, double w, const Vector3& g, const Vector3& offset)
      {
        sum += w;
        gradient_sum += g;
        position_sum += w * grid.node_position(key);
        gradient_of_position += grid.node_position(key) * g.transpose();
        offset_error = offset_error.cwiseMax((grid.node_position(key) - x - offset).cwiseAbs());
      });
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_LT(gradient_sum.norm(), 1e-9);
    EXPECT_LT((position_sum - x).norm(), 1e-15);
    EXPECT_LT((gradient_of_position - Eigen::Matrix3d::Identity()).norm(), 1e-11);
    EXPECT_LT(offset_error.maxCoeff(), 1e-15);
  }
}

TEST(GradedGrid, PointsFillEachGradedCellAndKeepTheBodysVolume)
{
  SceneParameters scene = test::empty_scene(Vector3(-12e-3, -6e-3, -12e-3),
                                            Vector3(12e-3, 14e-3, 12e-3), h);
  scene.materials.push_back(test::elastic_material("gel", 2e7, 1e5));
  BodyParameters block;
  block.name = "block";
  block.material = "gel";
  block.shape = BodyShape::cylinder;
  block.center = Vector3(0, 0, 0);
  block.axis = Vector3::UnitY();
  block.radius = 10e-3;
  block.length = 12e-3;
  block.nose = NoseShape::flat;
  block.particles_per_cell = 2;
  scene.bodies.push_back(block);
  scene.axisymmetric = true;
  const double exact = M_PI * 10e-3 * 10e-3 * 12e-3;
  double volume[2];
  std::size_t count[2];
  for (const bool graded : {false, true})
  {
    if (graded)
      scene.grading = grading(Vector3(-3e-3, -6e-3, -3e-3), Vector3(3e-3, 4e-3, 3e-3), 4.0, 2e-3);
    const Solver solver(scene);
    const Particles& p = solver.points();
    volume[graded] = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      volume[graded] += p.reference_volume[i];
    count[graded] = p.size();
    EXPECT_EQ(solver.background_grid().graded(), graded);
  }
  // The rings fill the cylinder exactly: its faces fall on the uniform lattice's sub-cells, and
  // the graded lattice lays a cut cell's points over the part inside the body's box.
  EXPECT_NEAR(volume[0] / exact, 1.0, 1e-9);
  EXPECT_NEAR(volume[1] / exact, 1.0, 1e-9);
  EXPECT_LT(count[1], 0.6 * count[0]);
}

namespace
{
/// The axisymmetry tests' ball into a gel cylinder (rigid steel ball of 2.5 mm radius at
/// 50 m/s along y into a gel cylinder of 8 mm radius, 10 mm long, free faces), 0.5 mm cells.
SceneParameters ball_into_gel(const bool graded)
{
  SceneParameters scene =
    test::empty_scene(Vector3(-10e-3, -6e-3, -10e-3), Vector3(10e-3, 12e-3, 10e-3), 0.5e-3);
  scene.axisymmetric = true;
  scene.materials.push_back(test::elastic_material("gel", 2e7, 1e5));
  scene.materials.push_back(test::rigid_material("steel"));
  BodyParameters gel;
  gel.name = "gel";
  gel.material = "gel";
  gel.shape = BodyShape::cylinder;
  gel.center = Vector3::Zero();
  gel.axis = Vector3::UnitY();
  gel.radius = 8e-3;
  gel.length = 10e-3;
  gel.nose = NoseShape::flat;
  gel.density = 1000.0;
  gel.particles_per_cell = 2;
  scene.bodies.push_back(gel);
  scene.bodies.push_back(test::steel_ball_projectile(Vector3(0, -2.6e-3, 0), 2.5e-3, 50.0));
  scene.contact.friction_coefficient = 0.0;
  scene.contact.exact_rigid_surface = true;
  scene.cell_volume_averaging = true;
  scene.end_time = 1.5e-4;
  if (graded)
    scene.grading = grading(Vector3(-4e-3, -6e-3, -4e-3), Vector3(4e-3, 6e-3, 4e-3), 4.0, 1e-3);
  return scene;
}
} // namespace

TEST(GradedGrid, ABallIntoAGelCylinderSlowsAsOnTheUniformGridAndKeepsItsAxialMomentum)
{
  double loss[2], travel[2];
  std::size_t points[2];
  for (const bool graded : {false, true})
  {
    Solver solver(ball_into_gel(graded));
    const SceneDiagnostics start = solver.diagnostics();
    const double y0 = start.bodies[1].centroid[1];
    while (!solver.finished())
      solver.advance();
    const SceneDiagnostics end = solver.diagnostics();
    loss[graded] = 50.0 - end.bodies[1].velocity[1];
    travel[graded] = end.bodies[1].centroid[1] - y0;
    points[graded] = solver.points().size();
    // Free faces and a frictionless rigid ball: nothing outside acts along the axis.
    EXPECT_NEAR(end.momentum[1], start.momentum[1], 1e-9 * std::abs(start.momentum[1]));
  }
  std::cout << "velocity loss " << loss[0] << " / " << loss[1] << " m/s, travel " << travel[0]
            << " / " << travel[1] << " m, points " << points[0] << " / " << points[1] << "\n";
  EXPECT_GT(loss[0], 3.0);
  EXPECT_NEAR(loss[1] / loss[0], 1.0, 0.03);
  EXPECT_NEAR(travel[1] / travel[0], 1.0, 0.005);
  EXPECT_LT(points[1], 0.75 * points[0]);
}
