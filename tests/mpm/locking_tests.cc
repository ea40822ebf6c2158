// The cell-averaged volume change of MPM points (F-bar): each cell's points share one volume
// change (their summed one, or the flux of the grid velocity through the cell), and every
// point keeps its isochoric part. The shear mode that shows it cures locking is in
// tests/fem/test_locking.cc (it shares the far field's scene).
#include "mpm/volume_averaging.h"

#include "materials/material.h"
#include "mpm/particle_to_grid.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vulnus;
using mpm::Vector3;
using Tensor2 = Eigen::Matrix3d;

TEST(MpmVolumeAveraging, PointsOfACellShareOneVolumeChangeAndKeepTheirShape)
{
  const mpm::Grid grid(Vector3::Zero(), Vector3(2e-3, 1e-3, 1e-3), 1e-3);
  mpm::Particles points;
  points.start_body();
  const Vector3 where[5] = {{0.2e-3, 0.5e-3, 0.5e-3}, {0.7e-3, 0.3e-3, 0.6e-3},
                            {0.5e-3, 0.8e-3, 0.2e-3}, {1.4e-3, 0.5e-3, 0.5e-3},
                            {1.6e-3, 0.5e-3, 0.5e-3}};
  const Tensor2 shear = (Tensor2() << 1.0, 0.1, 0.0, 0.0, 1.0, 0.05, 0.0, 0.0, 1.0).finished();
  const double j_old[5] = {1.0, 0.98, 1.03, 1.0, 1.0};
  const double j_new[5] = {1.01, 0.95, 1.04, 1.02, 0.99};
  mpm::VolumeAveraging scratch;
  scratch.prepare(grid, 5);
  for (int p = 0; p < 5; ++p)
  {
    points.append(where[p], Vector3::Zero(), 1e-7, 1e-10 * (1 + p), Vector3::UnitX());
    points.deformation_gradient[p] = std::cbrt(j_new[p]) * shear;
    scratch.j_old[p] = j_old[p];
    scratch.cell[p] = mpm::VolumeAveraging::cell_key(grid, where[p]);
  }
  points.finish_body();
  ASSERT_EQ(scratch.cell[0], scratch.cell[2]);
  ASSERT_NE(scratch.cell[0], scratch.cell[3]);
  double volume_before[2] = {0, 0}, volume_after[2] = {0, 0};
  for (int p = 0; p < 5; ++p)
    volume_before[p / 3] += points.reference_volume[p] * j_new[p];
  mpm::average_volume_changes(0, 5, points, scratch);
  for (int p = 0; p < 5; ++p)
  {
    const Tensor2& F = points.deformation_gradient[p];
    volume_after[p / 3] += points.reference_volume[p] * F.determinant();
    // The isochoric part is untouched.
    EXPECT_LT((F / std::cbrt(F.determinant()) - shear).norm(), 1e-12) << p;
  }
  for (int c = 0; c < 2; ++c)
    EXPECT_NEAR(volume_after[c], volume_before[c], 1e-12 * volume_before[c]) << c;
  // One volume change per cell.
  for (const auto& [a, b] : {std::pair{0, 1}, {0, 2}, {3, 4}})
    EXPECT_NEAR(points.deformation_gradient[a].determinant() / j_old[a],
                points.deformation_gradient[b].determinant() / j_old[b], 1e-12);
  // The second cell's points (volumes 4 and 5 units) change by (4 x 1.02 + 5 x 0.99) / 9.
  EXPECT_NEAR(points.deformation_gradient[3].determinant(), (4 * 1.02 + 5 * 0.99) / 9, 1e-12);
}

// Grid flux: a cell's volume ratio is that of the mean velocity gradient of its nodes (the
// flux through its faces), whatever its points' own gradients say. Four cells along x, nodal
// velocities v = (a x^2 + b y, c y, 0): the cell mean of dv_x/dx is a (x0 + x1) exactly, so
// the ratio is (1 + dt s)(1 + dt c) with s = a (x0 + x1) for forward Euler and
// (1 + dt s / 2)(1 + dt c / 2) / ((1 - dt s / 2)(1 - dt c / 2)) for the midpoint rule (L is
// upper triangular; the b y shear adds nothing). A cell less than half filled (the third)
// keeps its point's own change; one with a massless node (the fourth) its points' sum.
TEST(MpmVolumeAveraging, GridFluxGivesEachCellItsFacesVolumeChange)
{
  const double h = 1e-3, dt = 1e-6, a = 2e5, b = 50.0, c = -30.0;
  mpm::Grid grid(Vector3::Zero(), Vector3(4 * h, h, h), h);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 1; ++j)
      for (int k = 0; k <= 1; ++k)
        grid.mark(grid.node_key(i, j, k), 0);
  ASSERT_EQ(grid.number_active_nodes(1), 20u);
  std::vector<Vector3> velocity(20);
  std::vector<mpm::NodeBodyData> node_data(20);
  for (int slot = 0; slot < 20; ++slot)
  {
    const Vector3 x = grid.node_position(grid.active_keys()[slot]);
    velocity[slot] = Vector3(a * x[0] * x[0] + b * x[1], c * x[1], 0.0);
    node_data[slot].mass = x[0] > 3.5 * h ? 0.0 : 1e-6;
  }
  const Vector3 where[6] = {{0.2 * h, 0.5 * h, 0.5 * h}, {0.9 * h, 0.3 * h, 0.6 * h},
                            {1.5 * h, 0.8 * h, 0.2 * h}, {2.5 * h, 0.5 * h, 0.5 * h},
                            {3.4 * h, 0.5 * h, 0.5 * h}, {3.6 * h, 0.5 * h, 0.5 * h}};
  const double volume[6] = {0.6e-9, 0.6e-9, 0.6e-9, 0.1e-9, 0.6e-9, 0.6e-9};
  const Tensor2 shear = (Tensor2() << 1.0, 0.1, 0.0, 0.0, 1.0, 0.05, 0.0, 0.0, 1.0).finished();
  const double own_ratio[6] = {1.001, 0.999, 1.002, 1.004, 1.003, 0.998};
  for (const bool midpoint : {false, true})
  {
    mpm::Particles points;
    points.start_body();
    mpm::VolumeAveraging scratch;
    scratch.prepare(grid, 6);
    for (int p = 0; p < 6; ++p)
    {
      points.append(where[p], Vector3::Zero(), 1e-7, volume[p], Vector3::UnitX());
      points.deformation_gradient[p] = std::cbrt(own_ratio[p]) * shear;
      scratch.j_old[p] = 1.0;
      scratch.cell[p] = mpm::VolumeAveraging::cell_key(grid, where[p]);
    }
    points.finish_body();
    const mpm::NodalVelocities nodal{velocity, node_data, 1, 0, dt, midpoint};
    mpm::impose_grid_flux_volume_changes(grid, nodal, 0, 6, points, scratch);
    auto factor = [&](const double rate)
    {
      return midpoint ? (1 + 0.5 * dt * rate) / (1 - 0.5 * dt * rate) : 1 + dt * rate;
    };
    for (int p = 0; p < 3; ++p)
    {
      const double x0 = std::floor(where[p][0] / h) * h;
      const double expected = factor(a * (x0 + x0 + h)) * factor(c);
      const Tensor2& F = points.deformation_gradient[p];
      EXPECT_NEAR(F.determinant(), expected, 1e-13) << p << (midpoint ? " midpoint" : "");
      EXPECT_LT((F / std::cbrt(F.determinant()) - shear).norm(), 1e-12) << p;
    }
    EXPECT_NEAR(points.deformation_gradient[3].determinant(), 1.004, 1e-13);
    for (int p = 4; p < 6; ++p)
      EXPECT_NEAR(points.deformation_gradient[p].determinant(), (1.003 + 0.998) / 2, 1e-13) << p;
  }
}

// Grid flux's force pair: moved onto the cell's mean gradient, the volumetric forces of a
// cell's points do the work of the cell's flux. With the bilinear nodal velocities
// v = (b x y, c y, 0) the pair's power (the scatter with it less the scatter without it) is
// sigma_m sum_p V_p (div v(x_p) - div_cell): each point's own divergence b y_p + c (for uGIMP
// and CPDI its mean over the point's domain, which is symmetric about x_p) against the cell's
// b h / 2 + c. Its forces sum to zero (momentum); the shear stress, a debris point and a
// point alone in a cell it fills to 0.1 keep their own forces. The first cell's points
// (det F = 1.02) fill 0.61 of it. Once a corner of that cell holds none of the body's mass,
// the pair is undone and the plain scatter's forces are back.
TEST(MpmVolumeAveraging, GridFluxPairsTheVolumetricForcesWithTheCellsFlux)
{
  const double h = 1e-3, b = 2e5, c = -30.0, mean_stress = -3e6;
  const Vector3 where[5] = {{0.2 * h, 0.5 * h, 0.5 * h}, {0.9 * h, 0.3 * h, 0.6 * h},
                            {0.6 * h, 0.8 * h, 0.2 * h}, {1.5 * h, 0.5 * h, 0.5 * h},
                            {1.4 * h, 0.2 * h, 0.5 * h}};
  const double reference_volume[5] = {1e-10, 2e-10, 3e-10, 4e-10, 1e-10 / 1.02};
  // CPDI's domains are sheared, so its stencil is not the uGIMP box.
  const Tensor2 shear = (Tensor2() << 1.0, 0.6, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0).finished();
  for (const mpm::ShapeFunction shape :
       {mpm::ShapeFunction::linear, mpm::ShapeFunction::gimp, mpm::ShapeFunction::cpdi})
  {
    SCOPED_TRACE(static_cast<int>(shape));
    mpm::Grid grid(Vector3::Zero(), Vector3(2 * h, h, h), h);
    mpm::Particles points;
    points.start_body();
    for (int p = 0; p < 5; ++p)
    {
      points.append(where[p], Vector3::Zero(), 1e-7, reference_volume[p], Vector3::UnitX());
      points.deformation_gradient[p] =
        std::cbrt(1.02) * (shape == mpm::ShapeFunction::cpdi ? shear : Tensor2::Identity());
      points.stress[p].head<3>().setConstant(mean_stress);
      points.stress[p][3] = 1e5; // a shear stress the pair leaves alone
    }
    points.failure[3] = materials::total_failure;
    points.finish_body();
    mpm::TransferSettings transfer;
    transfer.shape = shape;
    transfer.half_size_cells = {0.25};
    mpm::mark_active_nodes(points, transfer, grid, true);
    mpm::ScatterBuffers buffers;
    mpm::GridFields plain, paired;
    mpm::particles_to_grid(points, grid, transfer, buffers, plain);
    mpm::VolumeAveraging scratch;
    scratch.clear_pair(5);
    mpm::prepare_grid_flux_pair(grid, 0, 5, points, scratch);
    const mpm::GridFluxPair pair{scratch.paired_stress.data(), scratch.cell.data()};
    mpm::particles_to_grid(points, grid, transfer, buffers, paired, nullptr, &pair);
    EXPECT_EQ(mpm::unpair_cells_without_mass(grid, transfer, 0, 0, 5, points, paired, scratch),
              0);
    double power = 0.0;
    Vector3 total = Vector3::Zero();
    for (std::size_t slot = 0; slot < grid.n_active(); ++slot)
    {
      const Vector3 x = grid.node_position(grid.active_keys()[slot]);
      const Vector3 pair_force = paired.data[slot].force - plain.data[slot].force;
      power += pair_force.dot(Vector3(b * x[0] * x[1], c * x[1], 0.0));
      total += pair_force;
      // Linear: the second cell's points alone reach these nodes.
      if (shape == mpm::ShapeFunction::linear && x[0] > 1.5 * h)
      {
        EXPECT_EQ(pair_force.norm(), 0.0) << slot;
      }
    }
    double expected = 0.0;
    for (int p = 0; p < 3; ++p)
      expected += mean_stress * 1.02 * reference_volume[p] * b * (where[p][1] - 0.5 * h);
    ASSERT_GT(std::abs(expected), 1e-6);
    EXPECT_NEAR(power, expected, 1e-9 * std::abs(expected));
    EXPECT_LT(total.norm(), 1e-12);

    paired.data[grid.slot(grid.node_key(0, 1, 1))].mass = 0.0;
    EXPECT_EQ(mpm::unpair_cells_without_mass(grid, transfer, 0, 0, 5, points, paired, scratch),
              3);
    for (std::size_t slot = 0; slot < grid.n_active(); ++slot)
      EXPECT_LT((paired.data[slot].force - plain.data[slot].force).norm(),
                1e-12 * plain.data[slot].force.norm() + 1e-18)
          << slot;
  }
}
