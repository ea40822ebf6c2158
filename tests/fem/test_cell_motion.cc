// A far-field cell's motion split into its affine part and the rest: rigid motion, uniform
// strain and a plane wave across a box cell are affine (nothing left), an hourglass mode is
// all left, and the distortion measures read the stretch and the turned corner they should.
#include "fem/cell_motion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace vulnus::fem;
using Eigen::Vector3d;

namespace
{
constexpr double h = 1e-3;

/// A box cell of edge h far from the origin, or the same cell with its corners moved.
CellNodes box_cell(const bool distorted = false)
{
  const Vector3d origin(0.1, -0.05, 0.2);
  CellNodes X;
  for (int a = 0; a < 8; ++a)
    X[a] = origin + h * Vector3d(a & 1, (a >> 1) & 1, (a >> 2) & 1);
  if (distorted)
  {
    X[3] += h * Vector3d(0.2, 0.1, -0.1);
    X[4] += h * Vector3d(-0.15, 0.05, 0.1);
  }
  return X;
}

template <class Map>
CellNodes displaced(const CellNodes& X, Map map)
{
  CellNodes u;
  for (int a = 0; a < 8; ++a)
    u[a] = map(X[a]) - X[a];
  return u;
}
} // namespace

TEST(CellMotion, RigidMotionOfAnySizeIsAffineAndUndistorted)
{
  const Eigen::Matrix3d R = Eigen::AngleAxisd(1.0, Vector3d(1, 2, 3).normalized()).matrix();
  for (const bool distorted : {false, true})
  {
    const CellNodes X = box_cell(distorted);
    const CellMotion m =
      cell_motion(X, displaced(X, [&](const Vector3d& x) { return Vector3d(R * x + Vector3d(0.03, -0.2, 0.01)); }), h);
    EXPECT_LT(m.non_affine, 1e-9);
    EXPECT_LT(m.deviatoric_stretch, 1e-9);
    EXPECT_LT((m.gradient - R).norm(), 1e-9);
  }
  const CellMotion box = cell_motion(box_cell(), displaced(box_cell(), [&](const Vector3d& x) { return Vector3d(R * x); }), h);
  EXPECT_NEAR(box.jacobian_ratio, 1.0, 1e-9);
}

TEST(CellMotion, UniformStretchIsAffineWithItsLogarithmicShapeChange)
{
  const Eigen::Matrix3d A = Eigen::Vector3d(1.3, 1.0, 0.8).asDiagonal();
  for (const bool distorted : {false, true})
  {
    const CellNodes X = box_cell(distorted);
    const CellMotion m = cell_motion(X, displaced(X, [&](const Vector3d& x) { return Vector3d(A * x); }), h);
    EXPECT_LT(m.non_affine, 1e-9);
    EXPECT_NEAR(m.deviatoric_stretch, std::log(1.3 / 0.8), 1e-12);
  }
  // A uniform dilatation changes no shape.
  const CellMotion dilated = cell_motion(box_cell(), displaced(box_cell(), [](const Vector3d& x) { return Vector3d(1.2 * x); }), h);
  EXPECT_LT(dilated.deviatoric_stretch, 1e-12);
}

// A plane wave along a box cell's axis moves each node by sin(k X); over one cell that is
// exactly affine along the axis when the nodes lie on two planes, whatever the amplitude.
TEST(CellMotion, APlaneWaveAlongTheCellsAxisIsAffine)
{
  const CellNodes X = box_cell();
  const double amplitude = 0.1 * h, k = 2.0 * M_PI / (10.0 * h);
  const CellMotion m = cell_motion(
    X, displaced(X, [&](const Vector3d& x) { return Vector3d(x + Vector3d(amplitude * std::sin(k * x[0]), 0, 0)); }), h);
  EXPECT_LT(m.non_affine, 1e-9);
}

// The hourglass mode (+-delta along x, the sign of the product of the corner's reference
// coordinates) has no linear part: it is left whole, delta per node.
TEST(CellMotion, AnHourglassModeIsLeftWhole)
{
  const CellNodes X = box_cell();
  const double delta = 0.05 * h;
  CellNodes u;
  for (int a = 0; a < 8; ++a)
  {
    const double sign = ((a & 1) ? 1 : -1) * (((a >> 1) & 1) ? 1 : -1) * (((a >> 2) & 1) ? 1 : -1);
    u[a] = Vector3d(sign * delta, 0, 0);
  }
  const CellMotion m = cell_motion(X, u, h);
  EXPECT_NEAR(m.non_affine, delta / h, 1e-12);
  EXPECT_LT((m.gradient - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

// Corner 0 pushed along its diagonal by s h: its edges become h (I - s 1 1^T), whose
// determinant is h^3 (1 - 3 s), while the far corner keeps h^3, so the ratio is 1 - 3 s and
// the corner turns inside out past s = 1/3.
TEST(CellMotion, APushedInCornerLowersTheJacobianRatioAndTurnsItInsideOut)
{
  const CellNodes X = box_cell();
  for (const double s : {0.1, 0.2, 0.3, 0.4})
  {
    CellNodes u;
    u.fill(Vector3d::Zero());
    u[0] = s * h * Vector3d(1, 1, 1);
    EXPECT_NEAR(cell_motion(X, u, h).jacobian_ratio, 1.0 - 3.0 * s, 1e-9);
  }
}
