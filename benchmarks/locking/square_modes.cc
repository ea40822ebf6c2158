// The shear and dilatational eigenmodes of a nearly incompressible square, in MPM and in the
// far field: their periods and their pressures against the analytic ones.
#include "benchmarks/locking/square_modes.h"

#include "benchmarks/locking/verification_gel.h"

#include "fem/far_field_solver.h"
#include "mpm/solver.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace vulnus::verification
{
namespace
{
constexpr double side = 10e-3, density = 1000.0, mu = verification_gel_shear_modulus;
const double k = M_PI / side;

/// The mode's shape, speed and exact fields at one bulk modulus.
struct ExactMode
{
  SquareMode mode;
  double bulk_modulus;
  double strain;

  double wave_speed() const
  {
    return std::sqrt((mode == SquareMode::shear ? mu : bulk_modulus + 4.0 / 3.0 * mu) / density);
  }
  double omega() const { return k * std::sqrt(2.0) * wave_speed(); }
  double period() const { return 2 * M_PI / omega(); }
  double initial_speed() const { return strain * std::sqrt(2.0) * wave_speed(); }
  double stress_scale() const
  {
    return 2.0 * strain * (mode == SquareMode::shear ? mu : bulk_modulus);
  }
  Eigen::Vector3d shape(const double x, const double y) const
  {
    const double sign = mode == SquareMode::shear ? -1.0 : 1.0;
    return Eigen::Vector3d(std::sin(k * x) * std::cos(k * y),
                           sign * std::cos(k * x) * std::sin(k * y), 0);
  }
  /// -K div u at time t of the mode started as initial_speed() * shape (zero for shear).
  double pressure(const double x, const double y, const double t) const
  {
    if (mode == SquareMode::shear)
      return 0.0;
    const double amplitude = initial_speed() / omega() * std::sin(omega() * t);
    return -bulk_modulus * amplitude * 2 * k * std::cos(k * x) * std::cos(k * y);
  }
};

/// Advances with `step` until the modal amplitude has crossed zero twice (or 1.5 T); on the
/// step after the first crossing, `record_pressures` writes the pressure errors into the result.
template <class Step, class Amplitude, class Time, class RecordPressures>
SquareModeResult measure(const ExactMode& exact, Step step, Amplitude amplitude, Time time,
                         RecordPressures record_pressures)
{
  const auto start = std::chrono::steady_clock::now();
  SquareModeResult r;
  double previous = amplitude(), previous_time = 0.0;
  std::vector<double> crossings;
  while (time() < 1.5 * exact.period() && crossings.size() < 2)
  {
    step();
    ++r.steps;
    const double a = amplitude();
    if ((previous > 0) != (a > 0))
    {
      crossings.push_back(previous_time + (time() - previous_time) * previous / (previous - a));
      if (crossings.size() == 1)
        record_pressures(r);
    }
    previous = a;
    previous_time = time();
  }
  if (crossings.size() == 2)
    r.period_ratio = 2.0 * (crossings[1] - crossings[0]) / exact.period();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

/// The cells' pressure errors (equal cells) as their root mean square and their mean.
void record_cell_errors(const std::vector<double>& errors, const double scale,
                        SquareModeResult& r)
{
  double sum = 0.0, sum2 = 0.0;
  for (const double e : errors)
  {
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(errors.size());
  r.pressure_error = std::sqrt(sum2 / n) / scale;
  r.mean_pressure_error = sum / n / scale;
}
} // namespace

SquareModeResult mpm_square_mode(const SquareMode mode, const unsigned int cells,
                                 const double bulk_over_shear, const PointVolume volume,
                                 const double strain, const mpm::VelocityTransfer transfer)
{
  const ExactMode exact{mode, bulk_over_shear * mu, strain};
  const double h = side / cells;
  mpm::SceneParameters scene;
  scene.domain_min = mpm::Vector3::Zero();
  scene.domain_max = mpm::Vector3(side, side, 2 * h);
  scene.cell_size = h;
  scene.end_time = 10 * exact.period();
  scene.stop_when_projectile_exits = false;
  scene.cfl = 0.4;
  scene.cell_volume_averaging = volume != PointVolume::own;
  scene.cell_volume_from_grid_flux = volume == PointVolume::grid_flux;
  scene.velocity_transfer = transfer;
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
  solver.set_point_velocities([&](const mpm::Vector3& x) -> mpm::Vector3
                              { return exact.initial_speed() * exact.shape(x[0], x[1]); });
  auto amplitude = [&]
  {
    const mpm::Particles& p = solver.points();
    double along = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
      const Eigen::Vector3d phi = exact.shape(p.position[i][0], p.position[i][1]);
      along += p.mass[i] * p.velocity[i].dot(phi);
      norm += p.mass[i] * phi.squaredNorm();
    }
    return along / norm;
  };
  auto record_pressures = [&](SquareModeResult& r)
  {
    const mpm::Particles& p = solver.points();
    const std::size_t n_cells = 2 * cells * cells;
    std::vector<double> cell_pressure(n_cells, 0.0), cell_volume(n_cells, 0.0);
    auto cell_index = [&](const mpm::Vector3& x)
    {
      std::size_t index[3];
      for (int axis = 0; axis < 3; ++axis)
        index[axis] = std::min<std::size_t>(static_cast<std::size_t>(std::max(0.0, x[axis] / h)),
                                            axis == 2 ? 1 : cells - 1);
      return index[0] + cells * (index[1] + cells * index[2]);
    };
    double point_error2 = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
      const mpm::Vector3& x = p.position[i];
      const double pressure = -(p.stress[i][0] + p.stress[i][1] + p.stress[i][2]) / 3.0;
      point_error2 += std::pow(pressure - exact.pressure(x[0], x[1], solver.time()), 2);
      const double volume = p.reference_volume[i] * p.deformation_gradient[i].determinant();
      const std::size_t cell = cell_index(x);
      cell_pressure[cell] += volume * pressure;
      cell_volume[cell] += volume;
    }
    std::vector<double> errors(n_cells);
    for (std::size_t c = 0; c < n_cells; ++c)
    {
      const double x = (static_cast<double>(c % cells) + 0.5) * h;
      const double y = (static_cast<double>(c / cells % cells) + 0.5) * h;
      errors[c] = cell_pressure[c] / cell_volume[c] - exact.pressure(x, y, solver.time());
    }
    record_cell_errors(errors, exact.stress_scale(), r);
    r.point_pressure_error =
        std::sqrt(point_error2 / static_cast<double>(p.size())) / exact.stress_scale();
  };
  return measure(
      exact, [&] { solver.advance(); }, amplitude, [&] { return solver.time(); },
      record_pressures);
}

SquareModeResult fe_square_mode(const SquareMode mode, const unsigned int cells,
                                const double bulk_over_shear, const bool averaging,
                                const fem::TimeIntegrator integrator, const bool one_point,
                                const double strain)
{
  using namespace dealii;
  const ExactMode exact{mode, bulk_over_shear * mu, strain};
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
  p.time_step = exact.period() / 80;
  p.newton_relative_tolerance = 1e-10;
  fem::FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();
  auto phi = [&](const Point<3>& x)
  {
    const Eigen::Vector3d m = exact.shape(x[0], x[1]);
    return Tensor<1, 3>({m[0], m[1], m[2]});
  };
  solver.set_initial_velocity([&](const Point<3>& x) { return exact.initial_speed() * phi(x); });
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
  auto record_pressures = [&](SquareModeResult& r)
  {
    std::vector<Point<3>> centres;
    std::vector<Tensor<2, 3>> stresses;
    solver.locally_owned_cell_stresses(centres, stresses);
    std::vector<double> errors(centres.size());
    for (std::size_t c = 0; c < centres.size(); ++c)
      errors[c] = -trace(stresses[c]) / 3.0 -
                  exact.pressure(centres[c][0], centres[c][1], solver.time());
    record_cell_errors(errors, exact.stress_scale(), r);
  };
  const bool explicit_steps = integrator == fem::TimeIntegrator::central_difference;
  return measure(
      exact,
      [&] { solver.advance(explicit_steps ? solver.next_time_step() : p.time_step); }, amplitude,
      [&] { return solver.time(); }, record_pressures);
}
} // namespace vulnus::verification
