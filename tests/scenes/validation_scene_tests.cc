// The FBI gelatin shot's decks (inputs/validation), coarsened and run for their first 0.15-0.2
// ms: the BB weighs its sphere's 0.340 g, enters and slows without stopping, its depth record
// is the nose's own, and momentum closes (bodies, supports, outflow); in the axisymmetric deck
// along the axis. The drag deck (benchmarks/drag) at 5 cells across its sphere: the force the
// medium exerts is the momentum the medium receives, and its drag coefficient lies between the
// converged one and the 5-cell excess docs/drag.md measures.
#include "deck_run.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vulnus;
using mpm::Vector3;

namespace
{
/// What the bodies hold, less the faces' impulse, plus what left the grid.
Vector3 momentum_accounted(const mpm::Solver& solver, const mpm::SceneDiagnostics& d)
{
  Vector3 now = solver.removed_momentum();
  for (const auto& body : d.bodies)
    now += body.mass * body.velocity;
  for (const Vector3& face : solver.support_impulses())
    now -= face;
  return now;
}
} // namespace

TEST(ValidationScene, GelatinShotEntersWithTheBbsExactMassAndClosesMomentum)
{
  const std::vector<deck::DeckOverride> coarse = {{"Grid/Cell size=0.002", "test"},
                                                  {"Time/End time=2e-4", "test"},
                                                  {"Output/Particle output interval=0", "test"}};
  const std::string deck_path = scene_tests::input_deck("validation/bb_gelatin10_reduced.prm");
  const double foremost_at_start =
    mpm::Solver(deck::read_run_parameters(deck_path, coarse).scene).diagnostics().bodies[1].max_along;
  const std::unique_ptr<mpm::Solver> run = scene_tests::run_to_end(deck_path, coarse);
  const mpm::Solver& solver = *run;
  const mpm::SceneDiagnostics d = solver.diagnostics();
  const int bb = solver.projectile();
  const double sphere_mass = 7624.0 * 4.0 / 3.0 * M_PI * std::pow(2.2e-3, 3);
  EXPECT_NEAR(d.bodies[bb].mass, sphere_mass, 1e-12 * sphere_mass);
  EXPECT_NEAR(sphere_mass, 0.340e-3, 0.0005e-3);

  // 0.2 ms at under 180 m/s: the nose is 1-3.6 cm deep, the BB slowed but moving on (to
  // 53 m/s: at 2 mm cells the grid's drag is several times the converged one,
  // docs/validation.md).
  const mpm::ProjectilePenetration& penetration = solver.penetration();
  EXPECT_TRUE(penetration.entered());
  EXPECT_FALSE(penetration.stopped());
  EXPECT_GT(penetration.max_depth(), 0.01);
  EXPECT_LT(penetration.max_depth(), 0.036);
  const double speed = d.bodies[bb].velocity[1];
  EXPECT_LT(speed, 175.0);
  EXPECT_GT(speed, 20.0);
  // The depth is the BB's front past the block's face y = 0: its sphere's pole at the start
  // (y = -2.3 + 2.2 mm), moved with its foremost point.
  EXPECT_EQ(solver.target_extent_along_flight().first, 0.0);
  const double front = -0.1e-3 + d.bodies[bb].max_along - foremost_at_start;
  EXPECT_NEAR(penetration.max_depth(), front, 1e-9);

  // A sphere turned about its centre stays where it is: its neglected rotation is not tracked.
  EXPECT_FALSE(solver.projectile_rotation().active());

  // Momentum: what the bodies hold now, the supports' impulse and the outflow make up the
  // BB's momentum at the start.
  EXPECT_LT((momentum_accounted(solver, d) - solver.initial_momentum()).norm(),
            1e-9 * sphere_mass * 180.0);
}

TEST(ValidationScene, AxisymmetricShotSlowsAndClosesMomentumAlongTheAxis)
{
  const std::vector<deck::DeckOverride> coarse = {{"Grid/Cell size=0.001", "test"},
                                                  {"Time/End time=1.5e-4", "test"},
                                                  {"Output/Particle output interval=0", "test"}};
  const std::string deck_path = scene_tests::input_deck("validation/fbi_bb_gelatin10.prm");
  const std::unique_ptr<mpm::Solver> run = scene_tests::run_to_end(deck_path, coarse);
  const mpm::Solver& solver = *run;
  ASSERT_TRUE(solver.background_grid().axisymmetric());
  const mpm::SceneDiagnostics d = solver.diagnostics();
  const int bb = solver.projectile();
  const double sphere_mass = 7624.0 * 4.0 / 3.0 * M_PI * std::pow(2.2e-3, 3);
  EXPECT_NEAR(d.bodies[bb].mass, sphere_mass, 1e-12 * sphere_mass);

  // 0.15 ms between 180 and 120 m/s: the nose 1.8-2.7 cm in, slowing, moving on along the axis.
  const mpm::ProjectilePenetration& penetration = solver.penetration();
  EXPECT_TRUE(penetration.entered());
  EXPECT_FALSE(penetration.stopped());
  EXPECT_GT(penetration.max_depth(), 0.018);
  EXPECT_LT(penetration.max_depth(), 0.027);
  EXPECT_LT(d.bodies[bb].velocity[1], 175.0);
  EXPECT_GT(d.bodies[bb].velocity[1], 100.0);
  EXPECT_EQ(d.bodies[bb].velocity[0], 0.0);
  EXPECT_EQ(d.bodies[bb].velocity[2], 0.0);

  // The revolved scene's momentum: nothing across the axis, and along it what the bodies hold,
  // the faces' impulse and the outflow make up the BB's momentum at the start.
  EXPECT_LT((momentum_accounted(solver, d) - solver.initial_momentum()).norm(),
            1e-9 * sphere_mass * 180.0);
  EXPECT_LT(std::abs(scene_tests::energy_balance_error(solver, d)), 0.01);
}

TEST(ValidationScene, DrivenSphereFeelsTheMomentumItGivesTheMedium)
{
  const char* dir = std::getenv("VULNUS_SOURCE_DIR");
  const std::string deck_path = std::string(dir ? dir : VULNUS_DEFAULT_SOURCE_DIR) +
                                "/benchmarks/drag/prescribed_sphere.prm";
  const std::vector<deck::DeckOverride> coarse = {{"Grid/Cell size=0.00088", "test"},
                                                  {"Time/End time=1.6e-4", "test"},
                                                  {"Output/Particle output interval=0", "test"}};
  mpm::Solver solver(deck::read_run_parameters(deck_path, coarse).scene);
  const int sphere = solver.projectile();
  const double a = 2.2e-3, speed = 180.0, rho = 1000.0;
  double impulse = 0.0, window_impulse = 0.0, window_time = 0.0;
  while (!solver.finished())
  {
    const double t0 = solver.time();
    solver.advance();
    const double dt = solver.time() - t0;
    const double force = -solver.contact_forces()[static_cast<std::size_t>(sphere)][1];
    impulse += force * dt;
    // The front 8-24 mm in, as benchmarks/drag/sphere_drag averages it.
    const double front = -0.1e-3 + speed * solver.time();
    if (front >= 8e-3 && front <= 24e-3)
    {
      window_impulse += force * dt;
      window_time += dt;
    }
  }
  ASSERT_GT(window_time, 0.0);
  // The medium's momentum along the axis, with what left the grid, is the impulse the
  // sphere's contact gave it (the revolved medium: nothing across the axis).
  const mpm::SceneDiagnostics d = solver.diagnostics();
  double medium = solver.removed_momentum()[1];
  for (std::size_t b = 0; b < d.bodies.size(); ++b)
    if (static_cast<int>(b) != sphere)
      medium += d.bodies[b].mass * d.bodies[b].velocity[1];
  EXPECT_NEAR(medium, impulse, 0.01 * impulse);
  // C_D: 0.486 at this cell, 0.325 extrapolated to a zero cell (docs/drag.md); between them
  // and at most 60 % above the limit.
  const double c_d = window_impulse / window_time / (0.5 * rho * speed * speed * M_PI * a * a);
  EXPECT_GT(c_d, 0.325);
  EXPECT_LT(c_d, 0.52);
}
