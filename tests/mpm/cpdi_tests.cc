// CPDI at large deformation: a uniformly deformed, uniformly stretching block passes through
// the transfer kernels unchanged (the patch test), and a hanging column stretched by half
// holds together and settles near the analytic equilibrium where linear and GIMP points tear
// apart.
#include "materials/material_registry.h"
#include "mpm/grid_to_particle.h"
#include "mpm/particle_to_grid.h"
#include "mpm/solver.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

using namespace vulnus;
using mpm::Tensor2;
using mpm::Vector3;

namespace
{
/// Largest change of F and position from the exact ones after one step of the transfer
/// kernels: points on a 2 x 2 x 2 lattice of a block deformed by F0, velocity L x with the
/// affine part C = L (APIC), forward Euler: exact is F <- (I + dt L) F0, x <- x + dt L x.
std::pair<double, double> patch_error(const mpm::ShapeFunction shape, const Tensor2& F0,
                                      const Tensor2& L)
{
  mpm::Grid grid(Vector3::Zero(), Vector3(12e-3, 12e-3, 12e-3), 1e-3);
  mpm::Particles particles;
  particles.start_body();
  const Vector3 origin(3.1e-3, 3.07e-3, 3.13e-3); // no point on a node: linear weights need a second node there
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i)
      {
        const Vector3 X = 0.25e-3 * Vector3(2 * i + 1, 2 * j + 1, 2 * k + 1);
        const Vector3 x = origin + F0 * X;
        particles.append(x, L * x, 1e-6, 0.125e-9, Vector3::UnitX());
        particles.deformation_gradient.back() = F0;
        particles.affine_velocity.back() = L.cast<float>();
      }
  particles.finish_body();
  const mpm::Particles before = particles;
  mpm::TransferSettings transfer;
  transfer.shape = shape;
  transfer.half_size_cells = {0.25};
  transfer.affine = true;
  mpm::mark_active_nodes(particles, transfer, grid);
  mpm::ScatterBuffers buffers;
  mpm::GridFields fields;
  mpm::particles_to_grid(particles, grid, transfer, buffers, fields);
  for (std::size_t e = 0; e < fields.data.size(); ++e)
    fields.velocity_new[e] =
      fields.data[e].mass > 0.0 ? Vector3(fields.data[e].momentum / fields.data[e].mass)
                                : Vector3::Zero();
  mpm::KinematicsSettings kinematics;
  kinematics.time_step = 1e-4;
  kinematics.deformation_update = mpm::DeformationUpdate::forward_euler;
  kinematics.body_is_rigid = {0};
  kinematics.rigid_velocity = {Vector3::Zero()};
  mpm::update_deformation_gradients_and_positions(grid, transfer, kinematics, fields,
                                                  fields.velocity_new, particles, nullptr);
  const Tensor2 F_exact = (Tensor2::Identity() + kinematics.time_step * L) * F0;
  double F_error = 0.0, x_error = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p)
  {
    F_error = std::max(F_error, (particles.deformation_gradient[p] - F_exact).norm());
    const Vector3 x = before.position[p];
    x_error = std::max(x_error, (particles.position[p] - (x + kinematics.time_step * L * x)).norm());
  }
  return {F_error, x_error};
}
} // namespace

// The lattice is stretched 2.5 times and sheared, so its points are 1.25 cells apart along x:
// the domains still tile it and every shape function is linearly complete, so the uniform
// velocity gradient (entries exact in the single-precision C) comes back to every point.
TEST(Cpdi, UniformDeformationPassesTheTransfersUnchanged)
{
  Tensor2 F0, L;
  F0 << 2.5, 0.5, 0.0, 0.0, 1.0, 0.25, 0.0, 0.0, 0.75;
  L << 0.5, -0.25, 0.0, 0.125, 1.0, 0.0, 0.0, 0.375, -0.5;
  for (const auto shape : {mpm::ShapeFunction::linear, mpm::ShapeFunction::gimp, mpm::ShapeFunction::cpdi})
  {
    const auto [F_error, x_error] = patch_error(shape, F0, L);
    EXPECT_LT(F_error, 1e-13) << "shape " << static_cast<int>(shape);
    EXPECT_LT(x_error, 1e-16) << "shape " << static_cast<int>(shape); // 1e-13 of the 1 mm cell
  }
}

namespace
{
constexpr double column_length = 10e-3, column_width = 2e-3, column_density = 1000.0;

/// Neo-Hookean column material that never yields (the elastic-plastic law's elasticity):
/// its pressure K/2 (J - 1/J) stiffens in tension, so the sudden load's overshoot stays
/// bounded, unlike the tissue law's K ln J / J.
mpm::NamedMaterial column_material()
{
  mpm::NamedMaterial m;
  m.name = "rubber";
  m.parameters.model = "elastic plastic";
  m.parameters.elastic_plastic.bulk_modulus = 3e4;
  m.parameters.elastic_plastic.shear_modulus = 1e4;
  m.parameters.elastic_plastic.yield_stress = 1e12;
  m.parameters.elastic_plastic.hardening_modulus = 0.0;
  return m;
}

/// Axial Cauchy stress, equal to the nominal one, in uniaxial strain F = diag(stretch, 1, 1).
double axial_stress(const materials::Material& material, const double stretch)
{
  materials::PointState state;
  materials::PointResponse response;
  material.update(Eigen::Vector3d(stretch, 1.0, 1.0).asDiagonal(), Vector3::UnitX(), state, response);
  return response.cauchy_stress(0, 0);
}

/// Analytic equilibrium of the column hanging from x = 0 under gravity g along +x: the
/// stretch lambda(X) carries the weight below, sigma(lambda) = rho g (L - X), and a point at
/// X sits at x(X) = int_0^X lambda. Tabulated at n + 1 points.
std::vector<double> hanging_positions(const materials::Material& material, const double g,
                                      const int n)
{
  std::vector<double> x(n + 1, 0.0);
  double previous = 0.0;
  for (int i = 0; i <= n; ++i)
  {
    const double X = column_length * i / n;
    const double load = column_density * g * (column_length - X);
    double low = 1.0, high = 10.0;
    for (int it = 0; it < 60; ++it)
    {
      const double mid = 0.5 * (low + high);
      (axial_stress(material, mid) < load ? low : high) = mid;
    }
    const double stretch = 0.5 * (low + high);
    if (i > 0)
      x[i] = x[i - 1] + 0.5 * (previous + stretch) * column_length / n;
    previous = stretch;
  }
  return x;
}

/// Runs the column until its points move slower than 2 mm/s (PIC damps the oscillations
/// the sudden load starts; 0.4 s at most) or a point leaves the grid (the column tore).
/// Returns the largest distance of a point from its analytic equilibrium position over the
/// tip's analytic displacement, and the largest speed at the end; a torn column gives
/// infinity.
std::pair<double, double> column_error(const mpm::ShapeFunction shape, const double h,
                                       const double g, const std::vector<double>& analytic)
{
  mpm::SceneParameters scene =
    test::empty_scene(Vector3::Zero(), Vector3(6 * column_length, column_width, column_width), h);
  scene.shape_function = shape;
  scene.velocity_transfer = mpm::VelocityTransfer::pic;
  // USL: MUSL's F follows the re-projected (twice smoothed) PIC velocities while the points
  // move with the grid's, so the transient leaves the column longer than its F says and it
  // tears whatever the shape functions.
  scene.update_scheme = mpm::UpdateScheme::usl;
  scene.cfl = 0.3;
  scene.gravity = Vector3(g, 0.0, 0.0);
  using F = mpm::FaceCondition;
  scene.domain_faces = {{F::fixed, F::free, F::roller, F::roller, F::roller, F::roller}};
  scene.materials.push_back(column_material());
  scene.bodies.push_back(test::box_body("column", "rubber", Vector3::Zero(),
                                        Vector3(column_length, column_width, column_width),
                                        column_density, 2));
  mpm::Solver solver(scene);
  std::map<std::uint32_t, double> reference;
  for (std::size_t p = 0; p < solver.points().size(); ++p)
    reference[solver.points().id[p]] = solver.points().position[p][0];
  auto fastest = [&]
  {
    double speed = 0.0;
    for (std::size_t p = 0; p < solver.points().size(); ++p)
      speed = std::max(speed, solver.points().velocity[p].norm());
    return speed;
  };
  try
  {
    for (int step = 1; solver.time() < 0.4 && (step % 100 != 0 || fastest() > 2e-3); ++step)
      solver.advance();
  }
  catch (const mpm::BlowUp&)
  {
    return {std::numeric_limits<double>::infinity(), fastest()};
  }
  const int n = static_cast<int>(analytic.size()) - 1;
  double worst = 0.0;
  for (std::size_t p = 0; p < solver.points().size(); ++p)
  {
    const double s = reference[solver.points().id[p]] / column_length * n;
    const int i = std::min(static_cast<int>(s), n - 1);
    const double expected = analytic[i] + (s - i) * (analytic[i + 1] - analytic[i]);
    worst = std::max(worst, std::abs(solver.points().position[p][0] - expected));
  }
  return {worst / (analytic[n] - column_length), fastest()};
}
} // namespace

// The column's top is stretched by half at rest and by about 1.8 in the first swing (points
// 0.9 cells apart). Linear and GIMP points separate there and the column tears; CPDI's
// domains keep it whole and it settles near the analytic equilibrium: 2.2 % of the tip's
// displacement at 1 mm, 1.6 % at 0.5 mm when the points have slowed below 2 mm/s (settled
// fully, 2.3 % and 2.2 %: the residue is a gap the transient leaves between the points'
// positions and their F, a few hundredths of a millimetre, not the resolution). The bound
// leaves 50 % on the coarse figure. Linear and GIMP are run beside it and printed for
// comparison, not asserted.
TEST(Cpdi, HangingColumnHoldsTogetherAndSettlesNearTheAnalyticEquilibrium)
{
  const auto material = materials::create_material(column_material().parameters);
  const double g = axial_stress(*material, 1.5) / (column_density * column_length);
  const std::vector<double> analytic = hanging_positions(*material, g, 2000);
  ASSERT_GT(analytic.back(), 1.2 * column_length); // the tip moves by over a fifth of the length
  const auto [coarse, coarse_speed] = column_error(mpm::ShapeFunction::cpdi, 1e-3, g, analytic);
  const auto [fine, fine_speed] = column_error(mpm::ShapeFunction::cpdi, 0.5e-3, g, analytic);
  std::printf("CPDI column: error / tip displacement %.4f (1 mm), %.4f (0.5 mm); speeds %.1e, "
              "%.1e m/s\n", coarse, fine, coarse_speed, fine_speed);
  for (const auto shape : {mpm::ShapeFunction::linear, mpm::ShapeFunction::gimp})
    std::printf("%s column at 1 mm: error / tip displacement %.4f (inf: torn)\n",
                mpm::shape_function_name(shape),
                column_error(shape, 1e-3, g, analytic).first);
  EXPECT_LT(coarse_speed, 2e-3);
  EXPECT_LT(fine_speed, 2e-3);
  EXPECT_LT(coarse, 0.035);
  EXPECT_LT(fine, 0.035);
}
