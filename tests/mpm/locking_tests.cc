// The cell-averaged volume change of MPM points (F-bar): each cell's points share one volume
// change, the cell keeps its volume and every point its isochoric part. The shear mode that
// shows it cures locking is in tests/fem/test_locking.cc (it shares the far field's scene).
#include "mpm/volume_averaging.h"

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
