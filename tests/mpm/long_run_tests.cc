// Runs that go on after the projectile has left the target: its exit is recorded when it
// happens (as in a run that stops there), the points that leave the grid are kept for the
// wound, and the target's momentum is accounted for by what left the grid and what the domain
// faces' supports gave it.
#include "analysis/mpm_summary.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

namespace vulnus
{
namespace
{
using mpm::Vector3;

/// The rigid ball through the gel slab, held by fixed side faces; points leaving are removed.
mpm::SceneParameters held_slab(const bool stop_at_exit, const double end_time)
{
  mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
  for (const int f : {0, 1, 4, 5})
    scene.domain_faces[f] = mpm::FaceCondition::fixed;
  scene.remove_points_leaving_grid = true;
  scene.stop_when_projectile_exits = stop_at_exit;
  scene.end_time = end_time;
  return scene;
}

Vector3 total_momentum(const mpm::Solver& solver)
{
  return solver.diagnostics().momentum;
}

TEST(MpmLongRun, RecordsTheExitAsTheRunThatStopsThere)
{
  mpm::Solver stopping(held_slab(true, 1e-3));
  while (!stopping.finished())
    stopping.advance();
  ASSERT_TRUE(stopping.projectile_exit().recorded);
  EXPECT_LT(stopping.time(), 1e-3); // it stopped at the exit

  mpm::Solver going_on(held_slab(false, 0.7e-3));
  const Vector3 p0 = total_momentum(going_on);
  double worst = 0.0;
  while (!going_on.finished())
  {
    going_on.advance();
    // Nothing else acts: what the points hold, plus what left, minus what the supports gave.
    std::array<Vector3, 6> supports = going_on.support_impulses();
    Vector3 given = Vector3::Zero();
    for (const Vector3& j : supports)
      given += j;
    worst = std::max(worst, (total_momentum(going_on) + going_on.removed_momentum() - given - p0).norm());
  }
  const mpm::ProjectileExit& a = stopping.projectile_exit();
  const mpm::ProjectileExit& b = going_on.projectile_exit();
  ASSERT_TRUE(b.recorded);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.kinetic_energy, b.kinetic_energy);
  // The ball has left the grid: every one of its points is kept as departed.
  const std::size_t ball_points = stopping.points().end_of(1) - stopping.points().begin_of(1);
  std::size_t departed_ball = 0;
  for (const mpm::DepartedPoint& d : going_on.departed_points())
    departed_ball += d.body == 1;
  EXPECT_EQ(departed_ball, ball_points);
  EXPECT_EQ(going_on.points().end_of(1) - going_on.points().begin_of(1), 0u);
  // The supports held the slab: a real share of the momentum went into them.
  const std::array<Vector3, 6> supports = going_on.support_impulses();
  double side_faces = 0.0;
  for (const int f : {0, 1, 4, 5})
    side_faces += supports[f][1];
  std::cout << "momentum: worst balance error " << worst << " kg m/s of " << p0.norm()
            << "; side faces' impulse along the flight " << side_faces << " N s\n";
  EXPECT_LT(side_faces, -1e-3 * p0.norm());
  EXPECT_EQ(supports[2].norm() + supports[3].norm(), 0.0); // free entrance and exit faces
  EXPECT_LT(worst, 1e-10 * p0.norm());
}
// A slow, light ball bounces off a stiff elastic slab: its tail never passes the exit plane, and the
// exit is recorded, going backwards, when none of its points is within a cell of the slab any
// more; the run stops there instead of running on to the end time.
TEST(MpmLongRun, ARicochetLeavesWhenTheProjectileIsClearOfTheTarget)
{
  mpm::SceneParameters scene = held_slab(true, 20e-3);
  scene.materials[0] = test::elastic_material("gel", 2e6, 2e5); // a stiff rubber
  scene.bodies[1].density = 1000.0;                             // a light ball
  scene.bodies[1].initial_velocity = Vector3(0, 2, 0);
  mpm::Solver solver(scene);
  while (!solver.finished())
    solver.advance();
  const mpm::ProjectileExit& exit = solver.projectile_exit();
  ASSERT_TRUE(exit.recorded);
  EXPECT_FALSE(exit.past_exit_plane);
  EXPECT_LT(solver.time(), 0.5 * scene.end_time);
  const mpm::Particles& p = solver.points();
  double highest = -1.0, slab_lowest = 1.0;
  for (std::size_t i = p.begin_of(1); i < p.end_of(1); ++i)
    highest = std::max(highest, p.position[i][1]);
  for (std::size_t i = p.begin_of(0); i < p.end_of(0); ++i)
    slab_lowest = std::min(slab_lowest, p.position[i][1]);
  EXPECT_LT(highest, slab_lowest - scene.cell_size); // more than a cell below the slab
  // It bounced: going back, at most at its initial speed (the gel is elastic, contact and
  // transfers dissipate a little).
  std::cout << "ricochet at t = " << exit.time << " s, velocity " << exit.velocity.transpose()
            << " m/s\n";
  EXPECT_LT(exit.velocity[1], -0.2 * 2.0);
  EXPECT_GT(exit.velocity[1], -2.0);
  // It slowed below the stop speed (1 m/s) inside before it turned: a stop, then a rebound.
  EXPECT_TRUE(solver.penetration().stopped());
  EXPECT_EQ(analysis::projectile_fate(exit, false, solver.penetration(), exit.velocity[1],
                                      scene.projectile_stop_speed),
            "stopped in the target, then left it backwards");
  // Its mass centre never passed the slab's far face: no exit wound, and the summary says so.
  const analysis::WoundSample sample = analysis::collect_wound_sample(solver);
  EXPECT_FALSE(analysis::left_through_exit_face(sample, solver));
  EXPECT_EQ(analysis::wound_metrics_of(sample, solver, 0.0).exit.face, -1);
}
} // namespace
} // namespace vulnus
