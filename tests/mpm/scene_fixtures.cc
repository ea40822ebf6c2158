// Small scenes for the MPM verification tests.
#include "scene_fixtures.h"

#include <cmath>

namespace vulnus::test
{
mpm::NamedMaterial elastic_material(const std::string& name, const double bulk_modulus,
                                    const double c1)
{
  mpm::NamedMaterial m;
  m.name = name;
  m.parameters.model = "isotropic hyperelastic";
  m.parameters.tissue.with_fibers = false;
  m.parameters.tissue.c1 = c1;
  m.parameters.tissue.c2 = 0.0;
  m.parameters.tissue.bulk_modulus = bulk_modulus;
  m.parameters.tissue.failure.enabled = false;
  return m;
}

mpm::NamedMaterial rigid_material(const std::string& name)
{
  mpm::NamedMaterial m;
  m.name = name;
  m.parameters.model = "rigid";
  return m;
}

mpm::BodyParameters box_body(const std::string& name, const std::string& material,
                             const mpm::Vector3& lower, const mpm::Vector3& upper,
                             const double density, const unsigned int particles_per_cell)
{
  mpm::BodyParameters b;
  b.name = name;
  b.material = material;
  b.shape = mpm::BodyShape::box;
  b.box_min = lower;
  b.box_max = upper;
  b.density = density;
  b.particles_per_cell = particles_per_cell;
  return b;
}

mpm::BodyParameters sphere_body(const std::string& name, const std::string& material,
                                const mpm::Vector3& center, const double radius,
                                const double density, const unsigned int particles_per_cell)
{
  mpm::BodyParameters b;
  b.name = name;
  b.material = material;
  b.shape = mpm::BodyShape::sphere;
  b.center = center;
  b.radius = radius;
  b.density = density;
  b.particles_per_cell = particles_per_cell;
  return b;
}

mpm::NamedMaterial soft_gelatin(const std::string& name, const double failure_plastic_strain)
{
  mpm::NamedMaterial gelatin;
  gelatin.name = name;
  gelatin.parameters.model = "elastic plastic";
  materials::ElasticPlasticParameters& e = gelatin.parameters.elastic_plastic;
  e.bulk_modulus = 5e6;
  e.shear_modulus = 0.85e6;
  e.yield_stress = 0.22e6;
  e.hardening_modulus = 0.0;
  e.volumetric_law = materials::VolumetricLawKind::hugoniot;
  e.failure_plastic_strain = failure_plastic_strain;
  return gelatin;
}

mpm::BodyParameters steel_ball_projectile(const mpm::Vector3& center, const double radius,
                                          const double speed)
{
  mpm::BodyParameters ball = sphere_body("ball", "steel", center, radius, 7800.0, 2);
  ball.initial_velocity = mpm::Vector3(0, speed, 0);
  ball.is_projectile = true;
  return ball;
}

mpm::SceneParameters two_gel_spheres(const double density_left, const double density_right,
                                     const mpm::Vector3& velocity_left,
                                     const mpm::Vector3& velocity_right)
{
  mpm::SceneParameters scene = empty_scene(mpm::Vector3(-12e-3, -6e-3, -6e-3), mpm::Vector3(12e-3, 6e-3, 6e-3), 1e-3);
  scene.materials.push_back(elastic_material("gel", 1e5, 1e4));
  scene.bodies.push_back(sphere_body("left", "gel", mpm::Vector3(-4e-3, 0, 0), 3e-3, density_left, 2));
  scene.bodies.push_back(sphere_body("right", "gel", mpm::Vector3(4e-3, 0, 0), 3e-3, density_right, 2));
  scene.bodies[0].initial_velocity = velocity_left;
  scene.bodies[1].initial_velocity = velocity_right;
  return scene;
}

mpm::SceneParameters SpinningBlock::scene(const mpm::VelocityTransfer transfer,
                                          const int series_order)
{
  mpm::SceneParameters scene =
    empty_scene(mpm::Vector3(-6e-3, -6e-3, -3e-3), mpm::Vector3(6e-3, 6e-3, 3e-3), 1e-3);
  scene.velocity_transfer = transfer;
  scene.series_order = series_order;
  scene.cfl = 0.3;
  scene.materials.push_back(elastic_material("gel", 1e5, 1e4));
  scene.bodies.push_back(box_body("block", "gel", mpm::Vector3(-3e-3, -3e-3, -1e-3),
                                  mpm::Vector3(3e-3, 3e-3, 1e-3), 1000.0, 2));
  return scene;
}

void SpinningBlock::start(mpm::Solver& solver)
{
  solver.set_point_velocities([](const mpm::Vector3& x)
                              { return mpm::Vector3(-omega * x[1], omega * x[0], 0); });
}

double SpinningBlock::energy_left(const mpm::SceneParameters& scene, const int steps)
{
  mpm::Solver solver(scene);
  start(solver);
  const double start = solver.diagnostics().kinetic_energy;
  for (int i = 0; i < steps; ++i)
    solver.advance();
  return solver.diagnostics().kinetic_energy / start;
}

double VibratingBar::wave_speed()
{
  return std::sqrt((bulk_modulus + 4.0 / 3.0 * 2.0 * c1) / density);
}

double VibratingBar::period() { return 4.0 * length / wave_speed(); }

mpm::SceneParameters VibratingBar::scene(const double cell_size)
{
  const double width = 2e-3;
  mpm::SceneParameters scene =
    empty_scene(mpm::Vector3::Zero(), mpm::Vector3(length + 6e-3, width, width), cell_size);
  scene.cfl = 0.3;
  using F = mpm::FaceCondition;
  scene.domain_faces = {{F::fixed, F::free, F::roller, F::roller, F::roller, F::roller}};
  scene.materials.push_back(elastic_material("gel", bulk_modulus, c1));
  scene.bodies.push_back(box_body("bar", "gel", mpm::Vector3::Zero(),
                                  mpm::Vector3(length, width, width), density, 2));
  return scene;
}

void VibratingBar::start_first_mode(mpm::Solver& solver) { start_mode(solver, 1); }

void VibratingBar::start_mode(mpm::Solver& solver, const int n)
{
  const double amplitude = 1e-3 * wave_speed();
  const double wave_number = (2 * n - 1) * M_PI / (2 * length);
  solver.set_point_velocities([&](const mpm::Vector3& x) {
    return mpm::Vector3(amplitude * std::sin(wave_number * x[0]), 0, 0);
  });
}

mpm::SceneParameters rigid_ball_into_gel_slab()
{
  mpm::SceneParameters scene = empty_scene(mpm::Vector3(-8e-3, -8e-3, -8e-3), mpm::Vector3(8e-3, 20e-3, 8e-3), 1e-3);
  scene.materials.push_back(elastic_material("gel", 2e5, 2.1e3));
  scene.materials.push_back(rigid_material("steel"));
  scene.bodies.push_back(box_body("slab", "gel", mpm::Vector3(-8e-3, 0, -8e-3), mpm::Vector3(8e-3, 4e-3, 8e-3), 1060.0, 2));
  mpm::BodyParameters ball = sphere_body("ball", "steel", mpm::Vector3(0, -3e-3, 0), 2.5e-3, 8930.0, 2);
  ball.initial_velocity = mpm::Vector3(0, 50, 0);
  ball.is_projectile = true;
  scene.bodies.push_back(ball);
  scene.end_time = 0.12e-3;
  return scene;
}

std::string run_until_blow_up(mpm::Solver& solver)
{
  try
  {
    while (!solver.finished())
      solver.advance();
  }
  catch (const mpm::BlowUp& e)
  {
    return e.what();
  }
  return "";
}

mpm::SceneParameters empty_scene(const mpm::Vector3& lower, const mpm::Vector3& upper,
                                 const double cell_size)
{
  mpm::SceneParameters s;
  s.domain_min = lower;
  s.domain_max = upper;
  s.cell_size = cell_size;
  s.end_time = 1.0;
  s.stop_when_projectile_exits = false;
  return s;
}
} // namespace vulnus::test
