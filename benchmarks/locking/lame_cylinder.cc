// The thick-walled cylinder under an imposed inner displacement, in the far field, against
// Lame's solution.
#include "benchmarks/locking/lame_cylinder.h"

#include "benchmarks/locking/verification_gel.h"
#include "fem/far_field_solver.h"
#include "fem/mesh_builder.h"

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <chrono>
#include <cmath>
#include <vector>

namespace vulnus::verification
{
namespace
{
constexpr double inner = 5e-3, outer = 10e-3, inner_strain = 1e-5;
constexpr double density = 1000.0;
/// Long enough that inertia is below 1e-10 of the stiffness (the shear wave crosses the wall
/// in about 1 ms).
constexpr double load_time = 10.0;

/// Lame's plane strain solution of the pushed wall, linear elasticity with mu and lambda. The
/// displacement's isochoric part is taken at finite strain, r = sqrt(R^2 + c) (exact for any
/// incompressible isotropic law; B = c / 2 at small strain), plus the volumetric A R: the
/// linear B / R alone differs from the hyperelastic answer by about 0.2 of the strain, more
/// than the F-bar element's own error.
struct Lame
{
  double mu, lambda, A, B, c;
  Lame(const double mu_, const double bulk) : mu(mu_), lambda(bulk - 2.0 * mu_ / 3.0)
  {
    const double delta = inner_strain * inner;
    B = delta / (mu * inner / ((lambda + mu) * outer * outer) + 1.0 / inner);
    A = mu * B / ((lambda + mu) * outer * outer);
    c = std::pow(inner + delta - A * inner, 2) - inner * inner;
  }
  double radial_displacement(const double r) const { return A * r + std::sqrt(r * r + c) - r; }
  double radial_stress(const double r) const
  {
    return 2 * (lambda + mu) * A - 2 * mu * B / (r * r);
  }
  double hoop_stress(const double r) const { return 2 * (lambda + mu) * A + 2 * mu * B / (r * r); }
  double pressure() const { return -(4 * (lambda + mu) * A + 2 * lambda * A) / 3.0; }
  dealii::Tensor<1, 3> displacement(const dealii::Point<3>& x) const
  {
    const double r = std::hypot(x[0], x[1]);
    return dealii::Tensor<1, 3>({x[0] / r, x[1] / r, 0.0}) * radial_displacement(r);
  }
};
} // namespace

LameResult lame_cylinder(const unsigned int radial_cells, const double bulk_over_shear,
                         const bool volume_averaging, const unsigned int degree)
{
  using namespace dealii;
  const auto start = std::chrono::steady_clock::now();
  const double h = (outer - inner) / radial_cells;
  const double mid_half_circumference = M_PI * 0.5 * (inner + outer);

  fem::FeSceneParameters p;
  p.slab_min = {{inner, 0.0, 0.0}};
  p.slab_max = {{outer, mid_half_circumference, h}};
  p.interface_cell_size = p.far_cell_size = h;
  p.material = verification_gel(bulk_over_shear);
  p.density = density;
  using Condition = fem::FaceParameters::Condition;
  p.faces[fem::boundary_ids::x_max].condition = Condition::free;
  for (const auto b : {fem::boundary_ids::x_min, fem::boundary_ids::y_min, fem::boundary_ids::y_max,
                       fem::boundary_ids::z_min, fem::boundary_ids::z_max})
    p.faces[b].condition = Condition::roller; // x_min is driven by the field below
  p.degree = degree;
  p.volume_averaging = volume_averaging;
  p.integrator = fem::TimeIntegrator::newmark;
  p.time_step = p.end_time = load_time;
  p.linear_solver = fem::LinearSolverType::direct;
  p.newton_relative_tolerance = 1e-10;

  const Lame exact(verification_gel_shear_modulus,
                   bulk_over_shear * verification_gel_shear_modulus);
  fem::FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.set_face_velocity_field(fem::boundary_ids::x_min, [&](const Point<3>& x, double)
                                 { return exact.displacement(x) / load_time; });
  // The box (r, s, z) becomes the half annulus: theta = pi s / (its length); both ends of
  // the s range land on the plane y = 0, where the y faces' rollers hold u_y.
  solver.setup(
      [&](Triangulation<3, 3>& tria)
      {
        GridTools::transform(
            [&](const Point<3>& x)
            {
              const double theta = M_PI * x[1] / mid_half_circumference;
              return Point<3>(x[0] * std::cos(theta), x[0] * std::sin(theta), x[2]);
            },
            tria);
      });
  solver.advance(load_time);

  LameResult r;
  r.radial_cells = radial_cells;
  r.cells = solver.n_active_cells();
  r.newton_iterations = solver.last_implicit_step().newton_iterations;

  double error2 = 0.0, norm2 = 0.0;
  for (const fem::NodeRecord& node : solver.locally_owned_nodes())
  {
    const Tensor<1, 3> u = exact.displacement(node.position);
    error2 += (solver.displacement(node) - u).norm_square();
    norm2 += u.norm_square();
  }
  r.displacement_error = std::sqrt(error2 / norm2);

  std::vector<Point<3>> centres;
  std::vector<Tensor<2, 3>> stresses;
  solver.locally_owned_cell_stresses(centres, stresses);
  const double scale = std::abs(exact.radial_stress(inner));
  double pressure2 = 0.0, radial2 = 0.0, hoop2 = 0.0;
  for (std::size_t c = 0; c < centres.size(); ++c)
  {
    const double radius = std::hypot(centres[c][0], centres[c][1]);
    const Tensor<1, 3> e_r({centres[c][0] / radius, centres[c][1] / radius, 0.0});
    const Tensor<1, 3> e_t({-e_r[1], e_r[0], 0.0});
    const Tensor<2, 3>& s = stresses[c];
    pressure2 += std::pow(-trace(s) / 3.0 - exact.pressure(), 2);
    radial2 += std::pow(e_r * (s * e_r) - exact.radial_stress(radius), 2);
    hoop2 += std::pow(e_t * (s * e_t) - exact.hoop_stress(radius), 2);
  }
  const double n = static_cast<double>(centres.size());
  r.pressure_error = std::sqrt(pressure2 / n) / scale;
  r.radial_stress_error = std::sqrt(radial2 / n) / scale;
  r.hoop_stress_error = std::sqrt(hoop2 / n) / scale;
  r.mean_pressure = -trace(solver.average_cauchy_stress()) / 3.0;
  r.exact_pressure = exact.pressure();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}
} // namespace vulnus::verification
