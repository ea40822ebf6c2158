// The signed distance to a body's exact shape (mpm/shape_distance.h) against an independent
// measurement: the nearest of many points sampled on the shape's surface, with the sign from
// the point generator's inside test (mpm/body_builder.h); the normal against the distance's
// finite-difference gradient.
#include "mpm/body_builder.h"
#include "mpm/shape_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace vulnus;
using mpm::Vector3;

namespace
{
/// Points on the surface of `body` (at its deck position), about `spacing` apart: found by
/// bisection along rays between inside and outside points of a fine lattice.
std::vector<Vector3> surface_samples(const mpm::BodyParameters& body, const double spacing)
{
  Vector3 lower, upper;
  mpm::body_bounding_box(body, lower, upper);
  lower.array() -= 2 * spacing;
  upper.array() += 2 * spacing;
  std::vector<Vector3> samples;
  const Vector3 steps[3] = {spacing * Vector3::UnitX(), spacing * Vector3::UnitY(),
                            spacing * Vector3::UnitZ()};
  for (double x = lower[0]; x <= upper[0]; x += spacing)
    for (double y = lower[1]; y <= upper[1]; y += spacing)
      for (double z = lower[2]; z <= upper[2]; z += spacing)
      {
        const Vector3 a(x, y, z);
        for (const Vector3& step : steps)
        {
          Vector3 inside = a, outside = a + step;
          const bool a_in = mpm::body_contains(body, inside);
          if (a_in == mpm::body_contains(body, outside))
            continue;
          if (!a_in)
            std::swap(inside, outside);
          for (int i = 0; i < 40; ++i)
          {
            const Vector3 middle = 0.5 * (inside + outside);
            (mpm::body_contains(body, middle) ? inside : outside) = middle;
          }
          samples.push_back(0.5 * (inside + outside));
        }
      }
  return samples;
}

/// For random points around `body`: |distance| equals the distance to the nearest surface
/// sample within `tolerance` (the samples' spacing bounds the error), the sign says inside,
/// and the normal is the distance's gradient. Inside a round-nosed cylinder (`exact_inside`
/// false) the distance is the nearer of the shank's and the nose's surfaces, which bounds the
/// whole shape's from below.
void expect_matches_samples(const mpm::BodyParameters& body, const double spacing,
                            const double tolerance, const bool exact_inside = true)
{
  const std::vector<Vector3> samples = surface_samples(body, spacing);
  ASSERT_GT(samples.size(), 100u);
  Vector3 lower, upper;
  mpm::body_bounding_box(body, lower, upper);
  const Vector3 margin = 0.3 * (upper - lower);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vector3 offset(1e-3, -2e-3, 0.5e-3);
  for (int n = 0; n < 300; ++n)
  {
    Vector3 x;
    for (int d = 0; d < 3; ++d)
      x[d] = lower[d] - margin[d] + unit(random) * (upper[d] - lower[d] + 2 * margin[d]);
    const mpm::ShapeDistance at = mpm::distance_to_shape(body, offset, x + offset);
    const bool inside = mpm::body_contains(body, x);
    double nearest = 1e9;
    for (const Vector3& s : samples)
      nearest = std::min(nearest, (s - x).norm());
    if (nearest < 2 * tolerance)
      continue; // too close to the surface for the sign to be tested against sampling
    EXPECT_EQ(at.distance < 0.0, inside) << "at " << x.transpose();
    if (!inside || exact_inside)
      EXPECT_NEAR(std::abs(at.distance), nearest, tolerance) << "at " << x.transpose();
    else
      EXPECT_LE(std::abs(at.distance), nearest + tolerance) << "at " << x.transpose();
    const double h = 1e-7;
    Vector3 gradient;
    for (int d = 0; d < 3; ++d)
    {
      Vector3 step = Vector3::Zero();
      step[d] = h;
      gradient[d] = (mpm::distance_to_shape(body, offset, x + offset + step).distance -
                     mpm::distance_to_shape(body, offset, x + offset - step).distance) /
                    (2 * h);
    }
    EXPECT_NEAR(at.normal.norm(), 1.0, 1e-12);
    EXPECT_LT((at.normal - gradient).norm(), 1e-5) << "at " << x.transpose();
  }
}
} // namespace

TEST(ShapeDistance, SphereMatchesItsSampledSurface)
{
  mpm::BodyParameters ball;
  ball.shape = mpm::BodyShape::sphere;
  ball.center = Vector3(0.01, 0.02, -0.01);
  ball.radius = 2.2e-3;
  expect_matches_samples(ball, 0.05e-3, 0.05e-3);
}

TEST(ShapeDistance, BoxMatchesItsSampledSurface)
{
  mpm::BodyParameters box;
  box.shape = mpm::BodyShape::box;
  box.box_min = Vector3(-1e-3, 0, 2e-3);
  box.box_max = Vector3(3e-3, 2e-3, 5e-3);
  expect_matches_samples(box, 0.05e-3, 0.05e-3);
}

TEST(ShapeDistance, CylindersMatchTheirSampledSurface)
{
  mpm::BodyParameters flat;
  flat.shape = mpm::BodyShape::cylinder;
  flat.center = Vector3(0, 1e-3, 0);
  flat.axis = Vector3(1, 2, 0.5).normalized();
  flat.radius = 1.5e-3;
  flat.length = 5e-3;
  flat.nose = mpm::NoseShape::flat;
  expect_matches_samples(flat, 0.05e-3, 0.05e-3);
  mpm::BodyParameters round = flat;
  round.nose = mpm::NoseShape::hemispherical;
  expect_matches_samples(round, 0.05e-3, 0.05e-3, false);
}

TEST(ShapeDistance, SphereCentreHasNoNormal)
{
  mpm::BodyParameters ball;
  ball.shape = mpm::BodyShape::sphere;
  ball.center = Vector3(1, 2, 3);
  ball.radius = 0.5;
  const mpm::ShapeDistance at = mpm::distance_to_shape(ball, Vector3(0.1, 0, 0), Vector3(1.1, 2, 3));
  EXPECT_DOUBLE_EQ(at.distance, -0.5);
  EXPECT_EQ(at.normal.squaredNorm(), 0.0);
}
