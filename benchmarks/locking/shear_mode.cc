// The divergence-free shear mode of a nearly incompressible square, in MPM and in the far field.
#include "benchmarks/locking/shear_mode.h"

#include "benchmarks/locking/verification_gel.h"

#include "fem/far_field_solver.h"
#include "mpm/solver.h"

#include <deal.II/base/mpi.h>

#include <chrono>
#include <cmath>
#include <vector>

namespace vulnus::verification
{
namespace
{
constexpr double side = 10e-3, density = 1000.0, mu = verification_gel_shear_modulus, strain = 1e-4;
const double k = M_PI / side;
const double shear_speed = std::sqrt(mu / density);
const double period = 2 * M_PI / (k * std::sqrt(2.0) * shear_speed);
const double v0 = strain * std::sqrt(2.0) * shear_speed;

Eigen::Vector3d mode(const double x, const double y)
{
  return Eigen::Vector3d(std::sin(k * x) * std::cos(k * y), -std::cos(k * x) * std::sin(k * y), 0);
}

/// Advances with `step` until the modal amplitude has crossed zero twice (or 1.5 T).
template <class Step, class Amplitude, class Time>
ShearModeResult measure(Step step, Amplitude amplitude, Time time)
{
  const auto start = std::chrono::steady_clock::now();
  ShearModeResult r;
  double previous = amplitude(), previous_time = 0.0;
  std::vector<double> crossings;
  while (time() < 1.5 * period && crossings.size() < 2)
  {
    step();
    ++r.steps;
    const double a = amplitude();
    if ((previous > 0) != (a > 0))
      crossings.push_back(previous_time + (time() - previous_time) * previous / (previous - a));
    previous = a;
    previous_time = time();
  }
  if (crossings.size() == 2)
    r.period_ratio = 2.0 * (crossings[1] - crossings[0]) / period;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

} // namespace

ShearModeResult mpm_shear_mode(const unsigned int cells, const double bulk_over_shear,
                               const bool averaging)
{
  const double h = side / cells;
  mpm::SceneParameters scene;
  scene.domain_min = mpm::Vector3::Zero();
  scene.domain_max = mpm::Vector3(side, side, 2 * h);
  scene.cell_size = h;
  scene.end_time = 10 * period;
  scene.stop_when_projectile_exits = false;
  scene.cfl = 0.4;
  scene.cell_volume_averaging = averaging;
  for (auto& face : scene.domain_faces)
    face = mpm::FaceCondition::roller;
  scene.materials.push_back({"gel", verification_gel(bulk_over_shear)});
  mpm::BodyParameters square;
  square.name = "square";
  square.material = "gel";
  square.shape = mpm::BodyShape::box;
  square.box_min = mpm::Vector3::Zero();
  square.box_max = scene.domain_max;
  square.density = density;
  square.particles_per_cell = 2;
  scene.bodies.push_back(square);
  mpm::Solver solver(scene);
  solver.set_point_velocities([](const mpm::Vector3& x) -> mpm::Vector3
                              { return v0 * mode(x[0], x[1]); });
  auto amplitude = [&]
  {
    const mpm::Particles& p = solver.points();
    double along = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
      const Eigen::Vector3d phi = mode(p.position[i][0], p.position[i][1]);
      along += p.mass[i] * p.velocity[i].dot(phi);
      norm += p.mass[i] * phi.squaredNorm();
    }
    return along / norm;
  };
  return measure([&] { solver.advance(); }, amplitude, [&] { return solver.time(); });
}

ShearModeResult fe_shear_mode(const unsigned int cells, const double bulk_over_shear,
                              const bool averaging, const fem::TimeIntegrator integrator,
                              const bool one_point)
{
  using namespace dealii;
  fem::FeSceneParameters p;
  const double h = side / cells;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{side, side, h}};
  p.interface_cell_size = p.far_cell_size = h;
  p.material = verification_gel(bulk_over_shear);
  p.density = density;
  for (auto& face : p.faces)
    face.condition = fem::FaceParameters::Condition::roller;
  p.volume_averaging = averaging;
  p.one_point_integration = one_point;
  p.integrator = integrator;
  p.time_step = period / 80;
  p.newton_relative_tolerance = 1e-10;
  fem::FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();
  auto phi = [](const Point<3>& x)
  {
    const Eigen::Vector3d m = mode(x[0], x[1]);
    return Tensor<1, 3>({m[0], m[1], m[2]});
  };
  solver.set_initial_velocity([&](const Point<3>& x) { return v0 * phi(x); });
  auto amplitude = [&]
  {
    double along = 0.0, norm = 0.0;
    for (const fem::NodeRecord& node : solver.locally_owned_nodes())
    {
      const Tensor<1, 3> m = phi(node.position);
      along += solver.velocity(node) * m;
      norm += m * m;
    }
    return along / norm;
  };
  const bool explicit_steps = integrator == fem::TimeIntegrator::central_difference;
  return measure([&] { solver.advance(explicit_steps ? solver.next_time_step() : p.time_step); },
                 amplitude, [&] { return solver.time(); });
}
} // namespace vulnus::verification
