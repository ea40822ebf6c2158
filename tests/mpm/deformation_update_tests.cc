// The midpoint update of F: the Cayley form (I - A)^-1 (I + A) F, and exact for a rigid spin.
#include "mpm/deformation_update.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <random>

using namespace vulnus::mpm;

TEST(MidpointUpdate, IsTheCayleyFormOfTheStep)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> small(-0.05, 0.05), entry(-1.0, 1.0);
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (int trial = 0; trial < 100; ++trial)
  {
    Eigen::Matrix3d A, F;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
      {
        A(i, j) = small(random);
        F(i, j) = (i == j ? 1.0 : 0.0) + 0.3 * entry(random);
      }
    const Eigen::Matrix3d expected = (I - A).inverse() * ((I + A) * F);
    EXPECT_LT((midpoint_update(A, F) - expected).norm(), 1e-14 * expected.norm()) << trial;
  }
}

TEST(MidpointUpdate, KeepsARigidSpinRigid)
{
  // A skew A turns F by an orthogonal matrix: lengths and the volume are kept to round-off.
  Eigen::Matrix3d A;
  A << 0.0, -0.03, 0.02, 0.03, 0.0, -0.01, -0.02, 0.01, 0.0;
  Eigen::Matrix3d F;
  F << 1.1, 0.2, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.2;
  const Eigen::Matrix3d turned = midpoint_update(A, F);
  const Eigen::Matrix3d Q = turned * F.inverse();
  EXPECT_LT((Q.transpose() * Q - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(turned.determinant(), F.determinant(), 1e-14);
}
