// Shape functions: partition of unity, zero gradient sum (reproduces constants), linear
// completeness (reproduces x), and gradients equal to finite differences of the weights.
#include "mpm/stencil.h"

#include <gtest/gtest.h>

#include <random>

using namespace vulnus::mpm;

namespace
{
template <ShapeFunction shape>
void check_reproduction(const double lp)
{
  const Grid grid(Vector3::Zero(), Vector3(4e-3, 4e-3, 4e-3), 1e-3);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.6e-3, 3.4e-3);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Vector3 x(coordinate(random), coordinate(random), coordinate(random));
    double sum = 0.0;
    Vector3 gradient_sum = Vector3::Zero();
    Vector3 position_sum = Vector3::Zero();
    Eigen::Matrix3d gradient_of_position = Eigen::Matrix3d::Zero();
    for_each_node<shape>(grid, lp, x, [&](std::int64_t key, double w, const Vector3& g) {
      sum += w;
      gradient_sum += g;
      position_sum += w * grid.node_position(key);
      gradient_of_position += grid.node_position(key) * g.transpose();
    });
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_LT(gradient_sum.norm(), 1e-9); // 1/h = 1e3 scale
    EXPECT_LT((position_sum - x).norm(), 1e-15);
    EXPECT_LT((gradient_of_position - Eigen::Matrix3d::Identity()).norm(), 1e-11);
  }
}

template <ShapeFunction shape>
void check_gradient_against_differences(const double lp)
{
  const Grid grid(Vector3::Zero(), Vector3(4e-3, 4e-3, 4e-3), 1e-3);
  const Vector3 x(1.37e-3, 2.11e-3, 1.93e-3);
  const double step = 1e-9;
  for_each_node<shape>(grid, lp, x, [&](std::int64_t key, double, const Vector3& g) {
    for (int d = 0; d < 3; ++d)
    {
      auto weight_at = [&](const Vector3& y) {
        double found = 0.0;
        for_each_node<shape>(grid, lp, y, [&](std::int64_t k, double w, const Vector3&) {
          if (k == key)
            found = w;
        });
        return found;
      };
      Vector3 plus = x, minus = x;
      plus[d] += step;
      minus[d] -= step;
      const double difference = (weight_at(plus) - weight_at(minus)) / (2 * step);
      // Weights are piecewise quadratic in x: central differences err by O(step) only at
      // kinks, which this point avoids; tolerance relative to 1/h = 1e3.
      EXPECT_NEAR(g[d], difference, 1e-3);
    }
  });
}
} // namespace

TEST(ShapeFunctions, LinearReproducesConstantsAndLinearFields)
{
  check_reproduction<ShapeFunction::linear>(0.0);
}

TEST(ShapeFunctions, GimpReproducesConstantsAndLinearFields)
{
  check_reproduction<ShapeFunction::gimp>(0.25);
  check_reproduction<ShapeFunction::gimp>(0.125);
}

TEST(ShapeFunctions, GradientsMatchFiniteDifferences)
{
  check_gradient_against_differences<ShapeFunction::linear>(0.0);
  check_gradient_against_differences<ShapeFunction::gimp>(0.25);
}

TEST(ShapeFunctions, GimpWeightIsContinuousAcrossItsBreakpoints)
{
  const double lp = 0.25;
  for (const double r : {lp, 1.0 - lp, 1.0 + lp})
  {
    double below, above, slope_below, slope_above;
    gimp_node_weight(r - 1e-12, lp, below, slope_below);
    gimp_node_weight(r + 1e-12, lp, above, slope_above);
    EXPECT_NEAR(below, above, 1e-10) << "at r = " << r;
    EXPECT_NEAR(slope_below, slope_above, 1e-10) << "at r = " << r;
  }
}
