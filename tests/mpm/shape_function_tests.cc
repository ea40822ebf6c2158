// Shape functions: partition of unity, zero gradient sum (reproduces constants), linear
// completeness (reproduces x), and gradients equal to finite differences of the weights
// (linear, GIMP) or the exact domain averages (CPDI).
#include "mpm/stencil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

using namespace vulnus::mpm;

namespace
{
const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();

template <ShapeFunction shape>
void check_reproduction(const double lp, const Eigen::Matrix3d& F = identity)
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
    for_each_node<shape>(grid, lp, x, F, [&](std::int64_t key, double w, const Vector3& g) {
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
  for_each_node<shape>(grid, lp, x, identity, [&](std::int64_t key, double, const Vector3& g) {
    for (int d = 0; d < 3; ++d)
    {
      auto weight_at = [&](const Vector3& y) {
        double found = 0.0;
        for_each_node<shape>(grid, lp, y, identity, [&](std::int64_t k, double w, const Vector3&) {
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

// CPDI: the corners' interpolant is linearly complete whatever the domain's shape, including
// domains stretched past the reach (shrunk) and sheared across cells.
TEST(ShapeFunctions, CpdiReproducesConstantsAndLinearFieldsForAnyDomain)
{
  Eigen::Matrix3d sheared;
  sheared << 1.3, 0.6, 0.0, -0.2, 0.8, 0.4, 0.1, 0.0, 1.1;
  const Eigen::Matrix3d stretched = Eigen::Vector3d(6.0, 0.5, 1.0).asDiagonal();
  for (const Eigen::Matrix3d& F : {identity, sheared, stretched, (sheared * stretched).eval()})
  {
    check_reproduction<ShapeFunction::cpdi>(0.25, F);
    check_reproduction<ShapeFunction::cpdi>(0.125, F);
  }
}

// An axis-aligned domain inside one cell: the tent functions are trilinear on it, so the CPDI
// weight and gradient are the exact averages over the box, which for a trilinear function are
// its value and gradient at the centre: the linear shape functions at the point.
TEST(ShapeFunctions, CpdiOfABoxInsideACellIsTheExactAverage)
{
  const Grid grid(Vector3::Zero(), Vector3(4e-3, 4e-3, 4e-3), 1e-3);
  const Vector3 x(1.52e-3, 2.47e-3, 1.55e-3);
  const Eigen::Matrix3d F = Eigen::Vector3d(1.6, 0.7, 1.2).asDiagonal(); // half-sizes 0.4, 0.175, 0.3
  std::map<std::int64_t, std::pair<double, Vector3>> linear, cpdi;
  for_each_node<ShapeFunction::linear>(grid, 0.0, x, identity,
                                       [&](std::int64_t key, double w, const Vector3& g)
                                       { linear[key] = {w, g}; });
  for_each_node<ShapeFunction::cpdi>(grid, 0.25, x, F,
                                     [&](std::int64_t key, double w, const Vector3& g)
                                     {
                                       auto& entry = cpdi.try_emplace(key, 0.0, Vector3::Zero()).first->second;
                                       entry.first += w;
                                       entry.second += g;
                                     });
  ASSERT_EQ(cpdi.size(), linear.size());
  for (const auto& [key, wg] : linear)
  {
    ASSERT_TRUE(cpdi.count(key));
    EXPECT_NEAR(cpdi[key].first, wg.first, 1e-14);
    EXPECT_LT((cpdi[key].second - wg.second).norm(), 1e-10); // gradients ~1e3 1/m
  }
}

// A domain crossing a cell face under pure shear: the weights are the domain averages of the
// corners' interpolant, computed here by Gauss quadrature of that interpolant over the
// parallelepiped (an independent path: no corner-mean or gradient formula).
TEST(ShapeFunctions, CpdiWeightsAreDomainAveragesOfTheCornerInterpolant)
{
  const Grid grid(Vector3::Zero(), Vector3(4e-3, 4e-3, 4e-3), 1e-3);
  const Vector3 x(1.93e-3, 2.08e-3, 1.5e-3);
  Eigen::Matrix3d F;
  F << 1.0, 0.9, 0.0, 0.0, 1.0, 0.0, 0.2, 0.0, 1.0;
  const double lp = 0.25;
  const Eigen::Matrix3d r = cpdi_half_vectors(F, lp) * grid.cell_size();
  auto tent = [&](const std::int64_t key, const Vector3& y)
  {
    const Vector3 d = (y - grid.node_position(key)) / grid.cell_size();
    return std::max(0.0, 1 - std::abs(d[0])) * std::max(0.0, 1 - std::abs(d[1])) *
           std::max(0.0, 1 - std::abs(d[2]));
  };
  std::map<std::int64_t, std::pair<double, Vector3>> cpdi;
  for_each_node<ShapeFunction::cpdi>(grid, lp, x, F,
                                     [&](std::int64_t key, double w, const Vector3& g)
                                     {
                                       auto& entry = cpdi.try_emplace(key, 0.0, Vector3::Zero()).first->second;
                                       entry.first += w;
                                       entry.second += g;
                                     });
  const double gauss[2] = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  for (const auto& [key, wg] : cpdi)
  {
    // Interpolant of the tent through the corners: trilinear in xi, integrated exactly by
    // 2-point Gauss; its xi-gradient mapped by r^-T.
    double mean = 0.0;
    Vector3 mean_gradient = Vector3::Zero();
    for (const double a : gauss)
      for (const double b : gauss)
        for (const double c : gauss)
        {
          const Vector3 xi(a, b, c);
          Vector3 d_xi = Vector3::Zero();
          for (int corner = 0; corner < 8; ++corner)
          {
            const Vector3 s(corner_sign(corner, 0), corner_sign(corner, 1), corner_sign(corner, 2));
            const double N = tent(key, x + r * s);
            const Vector3 f = (Vector3::Ones() + s.cwiseProduct(xi)) / 2.0;
            mean += N * f.prod() / 8.0;
            for (int k = 0; k < 3; ++k)
              d_xi[k] += N * s[k] / 2.0 * f.prod() / f[k];
          }
          mean_gradient += r.inverse().transpose() * d_xi / 8.0;
        }
    EXPECT_NEAR(wg.first, mean, 1e-14);
    EXPECT_LT((wg.second - mean_gradient).norm(), 1e-10);
  }
}

// However far a point's domain is stretched, its corners stay within a cell of it, so it
// touches only the nodes a GIMP stencil can (floor(s) - 1 .. floor(s) + 2 along each axis).
TEST(ShapeFunctions, CpdiStencilStaysWithinTheGimpReach)
{
  const Grid grid(Vector3::Zero(), Vector3(8e-3, 8e-3, 8e-3), 1e-3);
  const Vector3 x(3.99e-3, 4.01e-3, 4.5e-3);
  Eigen::Matrix3d F;
  F << 9.0, 5.0, 0.0, 4.0, 7.0, 0.0, 0.0, 0.0, 0.2;
  const Vector3 s = grid.to_cell_units(x);
  int visited = 0;
  for_each_node<ShapeFunction::cpdi>(grid, 0.25, x, F,
                                     [&](std::int64_t key, double, const Vector3&)
                                     {
                                       ++visited;
                                       const auto ijk = grid.node_ijk(key);
                                       for (int d = 0; d < 3; ++d)
                                       {
                                         EXPECT_GE(ijk[d], std::floor(s[d]) - 1);
                                         EXPECT_LE(ijk[d], std::floor(s[d]) + 2);
                                       }
                                     });
  EXPECT_GT(visited, 8);
  EXPECT_LE(visited, stencil_entries(ShapeFunction::cpdi));
}

// An F no material state should have (inverted, infinite, NaN) falls back to the reference
// box: the stencil stays a partition of unity within GIMP's reach instead of indexing
// through a NaN corner.
TEST(ShapeFunctions, CpdiOfAnUnphysicalFIsTheReferenceBox)
{
  const Grid grid(Vector3::Zero(), Vector3(8e-3, 8e-3, 8e-3), 1e-3);
  const Vector3 x(3.3e-3, 4.6e-3, 4.1e-3);
  const double inf = std::numeric_limits<double>::infinity();
  for (const Eigen::Matrix3d& F : {Eigen::Matrix3d(-Eigen::Matrix3d::Identity()),
                                   Eigen::Matrix3d(inf * Eigen::Matrix3d::Identity()),
                                   Eigen::Matrix3d(Eigen::Matrix3d::Constant(std::nan("")))})
  {
    std::map<std::int64_t, double> bad, reference;
    for_each_node<ShapeFunction::cpdi>(grid, 0.25, x, F,
                                       [&](std::int64_t key, double w, const Vector3&) { bad[key] += w; });
    for_each_node<ShapeFunction::cpdi>(grid, 0.25, x, Eigen::Matrix3d::Identity(),
                                       [&](std::int64_t key, double w, const Vector3&)
                                       { reference[key] += w; });
    ASSERT_EQ(bad.size(), reference.size());
    for (const auto& [key, w] : reference)
      EXPECT_DOUBLE_EQ(bad.at(key), w);
  }
}
