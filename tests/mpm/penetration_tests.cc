// Penetration runs: the projectile's depth record and the stop condition (a run that ends when
// the projectile stops or turns back), and the temporary cavity around its path.
#include "analysis/mpm_summary.h"
#include "analysis/temporary_cavity.h"
#include "mpm/projectile_penetration.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace vulnus
{
namespace
{
using mpm::Vector3;

TEST(ProjectilePenetration, KeepsTheDeepestPointTheStopAndACurveEveryResolution)
{
  mpm::ProjectilePenetration record(1e-3);
  record.record(0.0, -2e-3, 100.0, 1.0); // still outside: a slow speed would not count
  record.record(1e-6, -1e-3, 0.5, 1.0);
  EXPECT_FALSE(record.stopped());
  record.record(2e-6, 0.4e-3, 80.0, 1.0);
  record.record(3e-6, 1.2e-3, 60.0, 1.0);
  record.record(4e-6, 2.5e-3, 30.0, 1.0);
  record.record(5e-6, 2.9e-3, 0.8, 1.0); // stopped: at most 1 m/s inside the target
  record.record(6e-6, 2.8e-3, -0.5, 1.0);
  ASSERT_TRUE(record.stopped());
  EXPECT_EQ(record.stop().time, 5e-6);
  EXPECT_EQ(record.stop().depth, 2.9e-3);
  EXPECT_EQ(record.max_depth(), 2.9e-3);
  EXPECT_EQ(record.max_depth_time(), 5e-6);
  EXPECT_EQ(record.latest().depth, 2.8e-3);
  // The curve: the first sample, each one at least 1 mm deeper than the last kept, the stop.
  std::vector<double> depths;
  for (const mpm::PenetrationSample& s : record.curve())
    depths.push_back(s.depth);
  EXPECT_EQ(depths, (std::vector<double>{-2e-3, -1e-3, 0.4e-3, 2.5e-3, 2.9e-3}));

  mpm::ProjectilePenetration copy;
  copy.unpack(record.packed());
  EXPECT_EQ(copy.packed(), record.packed());
  EXPECT_THROW(copy.unpack({1.0, 2.0}), std::runtime_error);
}

/// The slow light ball of the ricochet test (long_run_tests.cc) on stiff rubber: it goes in,
/// stops and turns back without passing through.
mpm::SceneParameters bouncing_ball()
{
  mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
  for (const int f : {0, 1, 4, 5})
    scene.domain_faces[f] = mpm::FaceCondition::fixed;
  scene.materials[0] = test::elastic_material("gel", 2e6, 2e5);
  scene.bodies[1].density = 1000.0;
  scene.bodies[1].initial_velocity = Vector3(0, 2, 0);
  scene.end_time = 20e-3;
  scene.stop_when_projectile_stops = true;
  scene.projectile_stop_speed = 0.0;
  return scene;
}

TEST(Penetration, ARunEndsWhereTheProjectileTurnsBackAtItsDeepest)
{
  const mpm::SceneParameters scene = bouncing_ball();
  mpm::Solver solver(scene);
  const double entrance = solver.target_extent_along_flight().first;
  double previous_speed = 2.0;
  std::size_t steps = 0;
  while (!solver.finished())
  {
    solver.advance();
    ++steps;
    const mpm::ProjectilePenetration& p = solver.penetration();
    // The record is the particles' own: the foremost ball point, plus half its spacing,
    // below the slab's first points; the mass-centre speed along +y.
    const mpm::Particles& points = solver.points();
    double nose = -1.0, momentum = 0.0, mass = 0.0;
    for (std::size_t i = points.begin_of(1); i < points.end_of(1); ++i)
    {
      nose = std::max(nose, points.position[i][1]);
      momentum += points.mass[i] * points.velocity[i][1];
      mass += points.mass[i];
    }
    EXPECT_NEAR(p.latest().depth, nose + 0.25e-3 - entrance, 1e-15);
    EXPECT_NEAR(p.latest().speed, momentum / mass, 1e-12);
    if (!solver.finished())
      previous_speed = p.latest().speed;
  }
  const mpm::ProjectilePenetration& p = solver.penetration();
  ASSERT_TRUE(p.stopped());
  // It stopped at the first step whose speed was not positive, inside the slab, before it
  // could leave it again (the ricochet test's exit comes later), and never went through.
  EXPECT_LE(p.stop().speed, 0.0);
  EXPECT_GT(previous_speed, 0.0);
  EXPECT_GT(p.stop().depth, 0.0);
  EXPECT_FALSE(solver.projectile_exit().recorded);
  EXPECT_EQ(p.stop().time, solver.time());
  // Turning back at the stop: the deepest point is the stop's, to within one step's travel.
  EXPECT_LE(p.max_depth() - p.stop().depth,
            std::max(previous_speed, -p.stop().speed) * solver.last_time_step() + 1e-15);
  std::cout << "stopped after " << steps << " steps at t = " << p.stop().time << " s, depth "
            << p.stop().depth * 1e3 << " mm\n";
}

/// A soft gelatin-like block (the elastic-plastic law with the Hugoniot, failure at plastic
/// strain 0.9, Zochowski's shear modulus and yield; K lowered to 5 MPa so that the test takes
/// few steps) that a rigid steel ball enters at 12 m/s and stops in.
mpm::SceneParameters ball_into_gelatin()
{
  mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
  for (const int f : {0, 1, 4, 5})
    scene.domain_faces[f] = mpm::FaceCondition::fixed;
  scene.domain_max[1] = 16e-3;
  scene.bodies[0].box_max[1] = 12e-3;
  scene.remove_points_leaving_grid = true; // splash off the entrance face, booked as outflow
  mpm::NamedMaterial& gelatin = scene.materials[0];
  gelatin.parameters.model = "elastic plastic";
  materials::ElasticPlasticParameters& e = gelatin.parameters.elastic_plastic;
  e.bulk_modulus = 5e6;
  e.shear_modulus = 0.85e6;
  e.yield_stress = 0.22e6;
  e.hardening_modulus = 0.0;
  e.volumetric_law = materials::VolumetricLawKind::hugoniot;
  e.failure_plastic_strain = 0.9;
  scene.bodies[0].density = 1030.0;
  scene.bodies[1].initial_velocity = Vector3(0, 12, 0);
  scene.end_time = 20e-3;
  scene.stop_when_projectile_stops = true;
  return scene;
}

/// Runs the scene until the ball stops, asserting the momentum balance at every step;
/// returns the largest energy balance error of the run (relative to the start's energy).
double largest_energy_error_until_the_ball_stops(const mpm::SceneParameters& scene,
                                                 double* stop_depth)
{
  mpm::Solver solver(scene);
  const Vector3 initial_momentum = solver.initial_momentum();
  double largest_error = 0.0;
  std::size_t steps = 0;
  while (!solver.finished())
  {
    solver.advance();
    ++steps;
    const mpm::SceneDiagnostics d = solver.diagnostics();
    // Momentum: what the bodies hold, what the supports gave and what left the grid add up
    // to the start's (round-off of the sums over the points and the steps).
    Vector3 supplied = Vector3::Zero();
    for (const Vector3& impulse : solver.support_impulses())
      supplied += impulse;
    const Vector3 balance = d.momentum - supplied + solver.removed_momentum() - initial_momentum;
    EXPECT_LT(balance.norm(), 1e-9 * initial_momentum.norm()) << "step " << steps;
    largest_error = std::max(largest_error,
                             std::abs(analysis::relative_balance_error(
                                 analysis::accounted_energy(solver, d), solver.initial_energy())));
  }
  const mpm::ProjectilePenetration& p = solver.penetration();
  EXPECT_TRUE(p.stopped());
  EXPECT_FALSE(solver.projectile_exit().recorded);
  *stop_depth = p.stop().depth;
  std::cout << "stopped after " << steps << " steps at depth " << p.stop().depth * 1e3
            << " mm; largest energy balance error " << largest_error << "\n";
  return largest_error;
}

TEST(Penetration, ABallStopsInGelatinWithItsMomentumAndEnergyAccountedFor)
{
  double depth = 0.0;
  const double error = largest_energy_error_until_the_ball_stops(ball_into_gelatin(), &depth);
  EXPECT_GT(depth, 2.5e-3); // the ball went in
  EXPECT_LT(depth, 12e-3);  // and stopped inside
  // Every step the contact cancels the force at the nodes the ball holds, and the step loses
  // that force's kinetic energy, which no later step gives back: the contact books it (its
  // impulse works at the step's mean velocity). Measured 0.022 (1.0 % at half the step);
  // booking the correction at the trial velocities, as until stop 61, gave 0.295.
  EXPECT_LT(error, 0.04);
}

TEST(Penetration, AnElasticGelsEnergyBalanceClosesAsTheStepIsHalved)
{
  // Elastic gel (no yield): nothing but the contact and the time integration can lose energy.
  mpm::SceneParameters scene = ball_into_gelatin();
  scene.materials[0].parameters.elastic_plastic.yield_stress = 1e9;
  double depth = 0.0;
  const double error = largest_energy_error_until_the_ball_stops(scene, &depth);
  scene.cfl *= 0.5;
  double depth_half = 0.0;
  const double error_half = largest_energy_error_until_the_ball_stops(scene, &depth_half);
  // Measured 0.011 and 0.0053: first order in the step (the symplectic step's own energy
  // error), against 0.33 with the correction booked at the trial velocities.
  EXPECT_LT(error, 0.02);
  EXPECT_LT(error_half, 0.6 * error);
  EXPECT_NEAR(depth_half, depth, 0.05 * depth);
}

TEST(TemporaryCavity, ClosedBeforeTheBallAndAtLeastTheBallWhileItPasses)
{
  // The rigid 5 mm ball through the 4 mm gel slab at 50 m/s. Before it arrives the slices
  // measure only the lattice: 16 sectors around an axis between four points 0.5 mm apart
  // find their nearest point 0.35 to 0.8 mm out, an equivalent diameter of about 2.7
  // spacings, and that is the floor the summary reports; while it passes, no
  // stress-carrying gel point can lie inside it (grid contact lets the bodies overlap by at
  // most about a cell), so every slice opens to at least 2 (R - h) = 3 mm; and no cavity is
  // wider than the 16 mm slab.
  mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
  scene.stop_when_projectile_exits = false;
  mpm::Solver solver(scene);
  analysis::TemporaryCavity cavity(solver);
  ASSERT_TRUE(cavity.active());
  cavity.sample(solver);
  ASSERT_EQ(cavity.profile().size(), 4u); // the slab's points span 3.5 mm: four 1 mm slices
  for (const auto& slice : cavity.profile())
    EXPECT_LT(slice.max_diameter, 3 * 0.5e-3);
  EXPECT_EQ(cavity.resolution_floor(), cavity.largest().max_diameter);
  while (!solver.finished())
  {
    solver.advance();
    cavity.sample(solver);
  }
  for (const auto& slice : cavity.profile())
  {
    std::cout << "slice at " << slice.depth * 1e3 << " mm: largest " << slice.max_diameter * 1e3
              << " mm at " << slice.max_time * 1e6 << " us, now " << slice.diameter * 1e3 << " mm\n";
    EXPECT_GT(slice.max_diameter, 3e-3);
    EXPECT_LT(slice.max_diameter, 16e-3);
    EXPECT_GT(slice.max_time, 0.0);
  }
  analysis::TemporaryCavity copy;
  copy.unpack(cavity.packed());
  EXPECT_EQ(copy.packed(), cavity.packed());
}
} // namespace
} // namespace vulnus
