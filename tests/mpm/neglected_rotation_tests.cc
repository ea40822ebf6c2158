// A free rigid projectile only translates (mpm/neglected_rotation.h): the rotation its contact's
// moment would give, against hand-computed values, and a bullet yawed 20 degrees into gel,
// which as a rigid body never turned without a word.
#include "copper_ball.h"
#include "mpm/neglected_rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace vulnus;
using namespace vulnus::test;
using mpm::Vector3;

namespace
{
/// A rigid cylinder with a round nose (radius 2 mm, 8 mm long, of a polymer's density so that
/// its turn shows within the copper ball scene's 30 us) at 150 m/s along y into the ball's gel
/// slab, its axis `yaw_degrees` off the flight, its tip half a millimetre before the slab.
mpm::SceneParameters rigid_bullet_into_gel(const double yaw_degrees)
{
  BallSettings settings;
  settings.rigid = true;
  mpm::SceneParameters scene = copper_ball_scene(settings);
  scene.domain_min[1] = -12e-3; // room for its tail
  const double yaw = yaw_degrees * M_PI / 180.0;
  mpm::BodyParameters& bullet = scene.bodies[1];
  bullet.shape = mpm::BodyShape::cylinder;
  bullet.nose = mpm::NoseShape::hemispherical;
  bullet.radius = 2e-3;
  bullet.length = 8e-3;
  bullet.axis = Vector3(std::sin(yaw), std::cos(yaw), 0.0);
  bullet.center = Vector3(0.0, -0.5e-3, 0.0) - bullet.length * bullet.axis;
  bullet.density = 1060.0;
  return scene;
}
} // namespace

TEST(NeglectedRotation, TheFarthestPointPassingAQuarterCellIsRecordedOnce)
{
  // A moment of 1e-4 N m about the mass centre of a body of inertia 1e-9 kg m^2: after n steps
  // of 1e-6 s, omega = 0.1 n rad/s and the angle is 1e-7 n (n + 1) / 2; the farthest point
  // (5 mm) moves a quarter of the 1 mm cell first at n = 1000. A force through the moving
  // centre adds c x F to the moment about x = 0 and must not turn it.
  mpm::NeglectedRotation rotation;
  rotation.begin(Vector3::Zero(), 1e-9 * Eigen::Matrix3d::Identity(), 5e-3, 1e-3);
  const Vector3 v(0, 100, 0), force(0, 0, 5), torque(0, 0, 1e-4);
  const double dt = 1e-6;
  for (long n = 1; n <= 1200; ++n)
  {
    const Vector3 centre = (n - 1) * dt * v;
    rotation.add(force, centre.cross(force) + torque, v, dt, n, n * dt);
    if (n == 999)
    {
      EXPECT_EQ(rotation.exceeded_step(), -1);
    }
  }
  EXPECT_EQ(rotation.exceeded_step(), 1000);
  EXPECT_DOUBLE_EQ(rotation.exceeded_time(), 1000 * dt);
  EXPECT_NEAR(rotation.angle(), 1e-7 * 1200 * 1201 / 2, 1e-12);
  EXPECT_NEAR(rotation.drift(), 5e-3 * rotation.angle(), 1e-15);
  EXPECT_DOUBLE_EQ(rotation.drift_limit(), 0.25e-3);

  // Its state survives a checkpoint; a checkpoint of a body without the estimate does not
  // restore into one with it.
  mpm::NeglectedRotation copy;
  copy.begin(Vector3::Zero(), 1e-9 * Eigen::Matrix3d::Identity(), 5e-3, 1e-3);
  copy.unpack(rotation.packed());
  rotation.add(force, torque, v, dt, 1201, 1201 * dt);
  copy.add(force, torque, v, dt, 1201, 1201 * dt);
  EXPECT_EQ(copy.angle(), rotation.angle());
  EXPECT_EQ(copy.exceeded_step(), 1000);
  EXPECT_THROW(copy.unpack(mpm::NeglectedRotation().packed()), std::runtime_error);
}

TEST(NeglectedRotationScene, AYawedRigidBulletIsFlaggedAndAStraightOneIsNot)
{
  // Straight, the contact pushes through the axis: nothing to turn (round-off). Yawed 20
  // degrees, the gel pushes its nose aside; the rigid bullet only translates, and the
  // estimate passes the quarter cell during the run.
  mpm::Solver straight(rigid_bullet_into_gel(0.0));
  mpm::Solver yawed(rigid_bullet_into_gel(20.0));
  ASSERT_TRUE(straight.projectile_rotation().active());
  ASSERT_TRUE(yawed.projectile_rotation().active());
  while (!straight.finished())
    straight.advance();
  while (!yawed.finished())
    yawed.advance();
  const mpm::NeglectedRotation& s = straight.projectile_rotation();
  const mpm::NeglectedRotation& y = yawed.projectile_rotation();
  std::cout << "neglected rotation: straight " << s.angle() << " rad (" << s.drift()
            << " m), yawed " << y.angle() << " rad (" << y.drift() << " m), limit "
            << y.drift_limit() << " m, passed at step " << y.exceeded_step() << '\n';
  EXPECT_EQ(s.exceeded_step(), -1);
  EXPECT_LT(s.drift(), 0.01 * s.drift_limit());
  EXPECT_GT(y.exceeded_step(), 0);
  EXPECT_GT(y.drift(), y.drift_limit());
  // Only a free rigid projectile gets the estimate: not a held or deformable one.
  BallSettings held;
  held.hold = true;
  EXPECT_FALSE(mpm::Solver(copper_ball_scene(held)).projectile_rotation().active());
}
