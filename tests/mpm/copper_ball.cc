// The copper ball into gel, run to its end.
#include "copper_ball.h"

#include "scene_fixtures.h"

#include <algorithm>

namespace vulnus::test
{
using mpm::Vector3;

mpm::SceneParameters copper_ball_scene(const BallSettings& settings)
{
  mpm::SceneParameters scene =
    empty_scene(Vector3(-8e-3, -6e-3, -8e-3), Vector3(8e-3, 10e-3, 8e-3), 1e-3);
  scene.projectile_velocity_relaxation = settings.relaxation;
  scene.subcycle_projectile = settings.subcycle;
  scene.cfl = settings.cfl;
  scene.projectile_cfl = settings.projectile_cfl;
  scene.rigid_projectile_while_elastic = settings.hold;
  scene.rigid_projectile_stress_limit = settings.hold_limit;
  scene.artificial_viscosity_linear = 0.06; // the deck defaults
  scene.artificial_viscosity_quadratic = 1.5;
  scene.end_time = 30e-6; // the ball's nose 4 mm into the 6 mm slab
  scene.materials.push_back(elastic_material("gel", settings.gel_bulk_modulus, 2.1e3));
  mpm::NamedMaterial copper = rigid_material("copper");
  if (!settings.rigid)
    copper.parameters.model = "elastic plastic"; // the paper's bullet: K 117 GPa, mu 53.8 GPa
  scene.materials.push_back(copper);
  scene.bodies.push_back(box_body("slab", "gel", Vector3(-8e-3, 0, -8e-3),
                                  Vector3(8e-3, 6e-3, 8e-3), 1060.0, 2));
  mpm::BodyParameters ball = sphere_body("ball", settings.copper ? "copper" : "gel",
                                         Vector3(0, -3e-3, 0), 2.5e-3, 8930.0, 2);
  ball.initial_velocity = Vector3(0, 150, 0);
  ball.is_projectile = true;
  scene.bodies.push_back(ball);
  return scene;
}

BallRun fire_copper_ball(const BallSettings& settings)
{
  BallRun run;
  mpm::Solver solver(copper_ball_scene(settings));
  const mpm::SceneDiagnostics start = solver.diagnostics();
  int substeps = 0;
  while (!solver.finished())
  {
    solver.advance();
    substeps = std::max(substeps, solver.last_projectile_substeps());
    if (solver.projectile_hold().record().held)
    {
      const mpm::Particles& p = solver.points();
      const Vector3 first = p.velocity[p.begin_of(1)];
      for (std::size_t k = p.begin_of(1); k < p.end_of(1); ++k)
        run.max_ball_speed_spread = std::max(run.max_ball_speed_spread, (p.velocity[k] - first).norm());
    }
  }
  const mpm::SceneDiagnostics end = solver.diagnostics();
  run.subcycled = solver.subcycles_projectile();
  run.peak_yield_ratio = solver.peak_von_mises_over_yield()[1];
  run.ball_velocity = end.bodies[1].velocity[1];
  run.momentum_error = (end.momentum - start.momentum).norm() / start.momentum.norm();
  const double initial = solver.initial_energy();
  run.balance_error = (end.kinetic_energy + end.strain_energy + end.dissipated_energy +
                       solver.contact_dissipation() - initial) / initial;
  run.gel_kinetic_energy = end.bodies[0].kinetic_energy;
  run.steps = solver.step_count();
  run.time_step = solver.last_time_step();
  run.substeps = substeps;
  run.hold = solver.projectile_hold().record();
  run.hold_pressure_limit = solver.projectile_hold().pressure_limit();
  return run;
}
} // namespace vulnus::test
