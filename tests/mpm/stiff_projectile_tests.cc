// A copper ball (elastic-plastic, yield 423 MPa) fired at 150 m/s into a soft gel slab. The
// gel's stagnation pressure rho v^2 is 24 MPa, so the ball must stay elastic; with plain FLIP
// each contact impulse sets its surface ringing and the metal yields numerically. The
// projectile's velocity relaxation (at its own Courant time) must remove that, conserve
// momentum and book the energy it takes.
#include "mpm/solver.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vulnus;
using mpm::Vector3;

namespace
{
struct BallRun
{
  double peak_yield_ratio = 0.0; ///< max von Mises / flow stress of the ball over the run
  double ball_velocity = 0.0;    ///< m/s along the flight
  double momentum_error = 0.0;   ///< |p_end - p_start| / |p_start|
  double balance_error = 0.0;    ///< (E - E0) / E0 with the dissipation and contact losses
};

BallRun fire_copper_ball(const double projectile_relaxation)
{
  mpm::SceneParameters scene =
    test::empty_scene(Vector3(-8e-3, -6e-3, -8e-3), Vector3(8e-3, 10e-3, 8e-3), 1e-3);
  scene.projectile_velocity_relaxation = projectile_relaxation;
  scene.artificial_viscosity_linear = 0.06; // the deck defaults
  scene.artificial_viscosity_quadratic = 1.5;
  scene.end_time = 30e-6; // the ball's nose 4 mm into the 6 mm slab
  scene.materials.push_back(test::elastic_material("gel", 2e5, 2.1e3));
  mpm::NamedMaterial copper;
  copper.name = "copper";
  copper.parameters.model = "elastic plastic"; // the paper's bullet: K 117 GPa, mu 53.8 GPa
  scene.materials.push_back(copper);
  scene.bodies.push_back(test::box_body("slab", "gel", Vector3(-8e-3, 0, -8e-3),
                                        Vector3(8e-3, 6e-3, 8e-3), 1060.0, 2));
  mpm::BodyParameters ball =
    test::sphere_body("ball", "copper", Vector3(0, -3e-3, 0), 2.5e-3, 8930.0, 2);
  ball.initial_velocity = Vector3(0, 150, 0);
  ball.is_projectile = true;
  scene.bodies.push_back(ball);
  mpm::Solver solver(scene);
  const mpm::SceneDiagnostics start = solver.diagnostics();
  while (!solver.finished())
    solver.advance();
  const mpm::SceneDiagnostics end = solver.diagnostics();
  BallRun run;
  run.peak_yield_ratio = solver.peak_von_mises_over_yield()[1];
  run.ball_velocity = end.bodies[1].velocity[1];
  run.momentum_error = (end.momentum - start.momentum).norm() / start.momentum.norm();
  const double initial = solver.initial_energy();
  run.balance_error = (end.kinetic_energy + end.strain_energy + end.dissipated_energy +
                       solver.contact_dissipation() - initial) / initial;
  return run;
}
} // namespace

TEST(MpmStiffProjectile, RelaxationKeepsTheBallElasticAndConservesMomentum)
{
  const BallRun flip = fire_copper_ball(0.0);
  const BallRun relaxed = fire_copper_ball(0.1); // the deck default
  // The mechanism: plain FLIP yields the ball, as in the paper scenes.
  EXPECT_GE(flip.peak_yield_ratio, 1.0);
  // The physical peak is about rho v^2 / yield = 0.06 plus the impact stress of the first
  // contact; measured 0.69 (0.998 with a relaxation time of 0.5, 0.79 with 0.25). Bound 0.9:
  // room for the grid-scale contact pressure, not for yield.
  EXPECT_LT(relaxed.peak_yield_ratio, 0.9);
  // PIC and FLIP both conserve momentum (free faces, no gravity): round-off.
  EXPECT_LT(relaxed.momentum_error, 1e-10);
  EXPECT_LT(flip.momentum_error, 1e-10);
  // The relaxation damps the ball's ringing, not its flight: the deceleration by the gel
  // (18 m/s over the run for this small ball, rho v^2 A = 470 N) is the same within 0.5 m/s
  // (measured 0.3).
  EXPECT_LT(relaxed.ball_velocity, 150.0);
  EXPECT_NEAR(relaxed.ball_velocity, flip.ball_velocity, 0.5);
  // The energy the relaxation takes is booked: the balance error (the transfers' own loss at
  // the impact, measured 1.5 % with FLIP, 2.5 % relaxed) stays within 1.5 % of FLIP's.
  EXPECT_LT(std::abs(relaxed.balance_error), std::abs(flip.balance_error) + 0.015);
}
