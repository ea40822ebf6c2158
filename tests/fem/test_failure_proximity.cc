// How near a far-field point is to failing (the adaptive zone's criterion): under `any` the
// nearer of its matrix and fiber limits, infinite once either failed; under `total` the
// later of the two, a failed part counting as past its limit; without a fiber, the matrix's.
#include "fem/far_field_data.h"
#include "materials/two_surface_failure.h"

#include <gtest/gtest.h>

#include <limits>

using namespace vulnus;
using fem::FailureProximity;

namespace
{
constexpr double past = std::numeric_limits<double>::infinity();

/// Fiber along x stretched by 1.1 (a quarter of the way to 1.4) under a simple shear of 0.2
/// in the y-z plane, which leaves the fiber's length alone.
struct Point
{
  materials::FailureParameters criterion;
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Eigen::Vector3d fiber = Eigen::Vector3d::UnitX();
  Point()
  {
    F(0, 0) = 1.1;
    F(1, 2) = 0.2;
  }
  double matrix() const
  {
    return materials::matrix_shear_bound(criterion, F) / criterion.matrix_shear_limit;
  }
  double at(const std::uint8_t failure, const FailureProximity measure, const bool with_fiber = true) const
  {
    return fem::failure_proximity(criterion, F, with_fiber ? &fiber : nullptr, failure, measure);
  }
};
} // namespace

TEST(FailureProximity, AnyIsTheNearerPartAndInfiniteOnceEitherFailed)
{
  const Point p;
  const double fiber = 0.25;
  ASSERT_GT(p.matrix(), 0.0);
  ASSERT_NE(p.matrix(), fiber);
  EXPECT_NEAR(p.at(materials::intact, FailureProximity::any_failure), std::max(p.matrix(), fiber),
              1e-12);
  EXPECT_EQ(p.at(materials::matrix_failed, FailureProximity::any_failure), past);
  EXPECT_EQ(p.at(materials::fiber_failed, FailureProximity::any_failure), past);
  EXPECT_EQ(p.at(materials::total_failure, FailureProximity::any_failure), past);
}

TEST(FailureProximity, TotalIsThePartThatFailsLast)
{
  const Point p;
  const double fiber = 0.25;
  EXPECT_NEAR(p.at(materials::intact, FailureProximity::total_failure), std::min(p.matrix(), fiber),
              1e-12);
  EXPECT_NEAR(p.at(materials::matrix_failed, FailureProximity::total_failure), fiber, 1e-12);
  EXPECT_NEAR(p.at(materials::fiber_failed, FailureProximity::total_failure), p.matrix(), 1e-12);
  EXPECT_EQ(p.at(materials::total_failure, FailureProximity::total_failure), past);
}

TEST(FailureProximity, WithoutAFiberBothMeasuresAreTheMatrixs)
{
  const Point p;
  for (const FailureProximity measure :
       {FailureProximity::any_failure, FailureProximity::total_failure})
  {
    EXPECT_NEAR(p.at(materials::intact, measure, false), p.matrix(), 1e-12);
    EXPECT_EQ(p.at(materials::total_failure, measure, false), past);
  }
}
