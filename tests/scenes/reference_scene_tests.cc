// Uintah's reduced paper scene (inputs/reference), at vulnus's defaults and with every
// modelling choice as Uintah makes it, run for the first 30 microseconds: the bullet enters
// and slows, tissue fails around the tract, the energy balance closes, each deck's
// stress-after-failure rule holds at its failed points, and the bullet is held rigid while
// elastic at the defaults only.
#include "deck_run.h"
#include "materials/two_surface_failure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

using namespace vulnus;

namespace
{
struct EarlyRun
{
  double bullet_speed = 0.0;
  double bullet_tip = 0.0;
  std::size_t n_failed = 0;
  std::size_t totally_failed = 0;
  std::size_t totally_failed_with_stress = 0;
  double largest_failed_pressure = 0.0; ///< the largest compression a totally failed point carries
  double farthest_failure_from_axis = 0.0;
  double energy_error = 0.0;
  mpm::RigidHoldRecord hold;
  bool subcycled = false;
};

EarlyRun run_early(const std::string& deck_name)
{
  const std::unique_ptr<mpm::Solver> run = scene_tests::run_to_end(
    scene_tests::input_deck("reference/" + deck_name),
    {{"Time/End time=3e-5", "test"}, {"Output/Particle output interval=0", "test"}});
  const mpm::Solver& solver = *run;
  const mpm::SceneDiagnostics d = solver.diagnostics();
  EarlyRun r;
  const int bullet = solver.projectile();
  r.bullet_speed = d.bodies[bullet].velocity[1];
  r.bullet_tip = d.bodies[bullet].max_along;
  const mpm::Particles& p = solver.points();
  for (std::size_t i = p.begin_of(0); i < p.end_of(0); ++i)
  {
    if (p.failure[i] == 0)
      continue;
    ++r.n_failed;
    const mpm::Vector3 x = p.reference_position[i].cast<double>();
    r.farthest_failure_from_axis = std::max(r.farthest_failure_from_axis, std::hypot(x[0], x[2]));
    if ((p.failure[i] & materials::total_failure) != materials::total_failure)
      continue;
    ++r.totally_failed;
    const mpm::Tensor2 sigma = mpm::full_tensor(p.stress[i]);
    if (sigma.cwiseAbs().maxCoeff() > 0.0)
      ++r.totally_failed_with_stress;
    r.largest_failed_pressure = std::max(r.largest_failed_pressure, -sigma.trace() / 3.0);
  }
  r.energy_error = scene_tests::energy_balance_error(solver, d);
  r.hold = solver.projectile_hold().record();
  r.subcycled = solver.subcycles_projectile();
  return r;
}

void expect_a_bullet_entering(const EarlyRun& r, const double energy_bound)
{
  // 30 microseconds at 150 m/s: the nose, 1 mm before the slab, is about 3.5 mm inside.
  EXPECT_GT(r.bullet_tip, 2.5e-3);
  EXPECT_LT(r.bullet_tip, 4.5e-3);
  EXPECT_LT(r.bullet_speed, 150.0);
  EXPECT_GT(r.bullet_speed, 120.0);
  EXPECT_GT(r.n_failed, 500u);
  // Around the tract (bullet radius 4.5 mm), a few cells at most beyond it.
  EXPECT_LT(r.farthest_failure_from_axis, 9e-3);
  EXPECT_LT(std::abs(r.energy_error), energy_bound);
}
} // namespace

TEST(ReferenceScene, UintahReducedSceneAtTheDefaultsKeepsDebrisPressure)
{
  const EarlyRun r = run_early("uintah_reduced.prm");
  // The converged defaults close the balance within 1 % over the whole run.
  expect_a_bullet_entering(r, 0.02);
  // Debris rule: crushed failed tissue resists compression.
  ASSERT_GT(r.totally_failed, 100u);
  EXPECT_GT(r.totally_failed_with_stress, 0u);
  EXPECT_GT(r.largest_failed_pressure, 0.0);
  // The copper bullet meets 2.2 MPa at the impact and about 50 MPa in the crushed tissue
  // ahead of it, against 211 MPa, half its yield stress: held rigid, with no substeps.
  EXPECT_TRUE(r.hold.held);
  EXPECT_FALSE(r.subcycled);
  EXPECT_GT(r.hold.peak_pressure, 1e7);
  EXPECT_LT(r.hold.peak_pressure, 0.5 * 422.6e6);
}

TEST(ReferenceScene, UintahReducedSceneAsUintahRunsOnWithStressFreeFailedPoints)
{
  // The paper's rule: totally failed tissue carries nothing, also where it is crushed, and
  // the run goes on (a failed point its step would invert is crushed to debris).
  const EarlyRun r = run_early("uintah_reduced_as_uintah.prm");
  // Uintah's first contact pass changes velocities that the FLIP increments leave out: the
  // balance misses 18 % over the whole run, as Uintah's own misses 37 %
  // (docs/uintah_side_by_side.md). The bound catches a blow-up, not that error.
  expect_a_bullet_entering(r, 0.3);
  ASSERT_GT(r.totally_failed, 100u);
  EXPECT_EQ(r.totally_failed_with_stress, 0u);
  // Uintah's bullet is deformable throughout, and steps with the scene.
  EXPECT_FALSE(r.hold.applies);
  EXPECT_FALSE(r.subcycled);
}
