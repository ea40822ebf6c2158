// The nonlocal failure criterion: the mean over the radius l returns a uniform field and
// smooths a step over l whatever the point spacing (against the mean of the bell kernel
// integrated analytically); failure then needs the measure above its limit over a region of
// about l, and a failed zone's width is set by l, not by the spacing.
#include "materials/material_registry.h"
#include "materials/two_surface_failure.h"
#include "mpm/nonlocal_average.h"
#include "mpm/nonlocal_failure.h"
#include "mpm/stress_update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>
#include <memory>

using namespace vulnus;
using mpm::Vector3;

namespace
{
/// One body of points on a cubic lattice of spacing h over [-half_x, half_x] x [-half, half]^2.
mpm::Particles lattice(const double h, const double half_x, const double half)
{
  mpm::Particles points;
  points.start_body();
  const int nx = static_cast<int>(std::round(2 * half_x / h)), n = static_cast<int>(std::round(2 * half / h));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < nx; ++i)
        points.append(Vector3(-half_x + (i + 0.5) * h, -half + (j + 0.5) * h, -half + (k + 0.5) * h),
                      Vector3::Zero(), 1e3 * h * h * h, h * h * h, Vector3::UnitX());
  points.finish_body();
  return points;
}

/// Share of the bell kernel's weight beyond the plane x = 0 seen from x0 (both in units of
/// l): its marginal along x is proportional to (1 - t^2)^3.
double analytic_step_mean(const double x0)
{
  auto primitive = [](const double t) { return t - t * t * t + 0.6 * std::pow(t, 5) - std::pow(t, 7) / 7.0; };
  const double lower = std::clamp(-x0, -1.0, 1.0);
  return (primitive(1.0) - primitive(lower)) / (primitive(1.0) - primitive(-1.0));
}

/// The nonlocal mean of a unit step at x = 0 at the point nearest to x = x0, and that
/// point's x.
std::pair<double, double> step_mean_near(const mpm::Particles& points, const double l,
                                         const double x0)
{
  const mpm::NonlocalNeighbourhood neighbourhood(points, 0, points.size(), l);
  std::vector<double> values(points.size());
  const std::vector<char> all(points.size(), 1);
  std::size_t nearest = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    const Vector3 x = points.position[p];
    values[p] = x[0] > 0.0 ? 1.0 : 0.0;
    const Vector3 target(x0, 0, 0), best = points.position[nearest];
    if ((x - target).norm() < (best - target).norm())
      nearest = p;
  }
  return {neighbourhood.mean(nearest, neighbourhood.in_cell_order(values.data()).data(),
                            all.data()),
          points.position[nearest][0]};
}

/// The isotropic tissue law with failure on and the nonlocal criterion over l (0: local).
std::unique_ptr<materials::Material> gel(const double l)
{
  materials::MaterialParameters m;
  m.model = "isotropic hyperelastic";
  m.tissue.with_fibers = false;
  m.tissue.failure.enabled = true;
  m.tissue.failure.matrix_shear_limit = 0.5;
  m.tissue.failure.regularization_length = l;
  return materials::create_material(m);
}

/// Points of a lattice inside a band |y| < width / 2 stretched isochorically along x (shear
/// measure 0.62, 1.25 times the limit 0.5), the rest unstrained; the criterion decides and
/// the stress update applies. Returns the band of failed points: the largest |y| failed.
double failed_half_width(const double h, const double l, const double width)
{
  mpm::Particles points = lattice(h, 4e-3, 8e-3);
  const double stretch = 1.4;
  const mpm::Tensor2 F = Eigen::Vector3d(stretch, 1 / std::sqrt(stretch), 1 / std::sqrt(stretch)).asDiagonal();
  for (std::size_t p = 0; p < points.size(); ++p)
    if (std::abs(points.position[p][1]) < 0.5 * width)
      points.deformation_gradient[p] = F;
  const std::unique_ptr<materials::Material> law = gel(l);
  const std::vector<const materials::Material*> bodies{law.get()};
  mpm::NonlocalFailureCache cache;
  if (l > 0.0)
    mpm::decide_nonlocal_failures(bodies, points, cache);
  mpm::StressUpdateSettings settings;
  settings.time_step = 1e-6;
  settings.cell_size = h;
  settings.body_material = bodies;
  settings.body_density = {1e3};
  mpm::StressUpdateResult result;
  mpm::update_stresses(settings, nullptr, points, result);
  double half_width = 0.0;
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    EXPECT_EQ(points.failure[p] & ~materials::total_failure, 0) << "marks left behind";
    if (points.failure[p] & materials::matrix_failed)
      half_width = std::max(half_width, std::abs(points.position[p][1]));
  }
  return half_width;
}
} // namespace

TEST(NonlocalAverage, AUniformFieldIsReturned)
{
  const mpm::Particles points = lattice(0.5e-3, 3e-3, 3e-3);
  const mpm::NonlocalNeighbourhood neighbourhood(points, 0, points.size(), 1.5e-3);
  const std::vector<double> values(points.size(), 0.7);
  const std::vector<char> all(points.size(), 1);
  const std::vector<double> sorted = neighbourhood.in_cell_order(values.data());
  for (std::size_t p = 0; p < points.size(); p += 7)
    EXPECT_NEAR(neighbourhood.mean(p, sorted.data(), all.data()), 0.7, 1e-14);
}

TEST(NonlocalAverage, AStepIsSmoothedOverTheLengthNotTheSpacing)
{
  // l = 2 mm; spacings l/4 and l/8. The lattice's quadrature of the kernel is off by 0.005
  // at l/4 and 0.0012 at l/8 (measured; second order): both follow the analytic profile, so
  // the smoothing is the kernel's, not the spacing's.
  const double l = 2e-3;
  for (const double h : {0.5e-3, 0.25e-3})
  {
    const mpm::Particles points = lattice(h, 6e-3, 5e-3);
    for (const double x0 : {-0.75, -0.5, -0.25, 0.25, 0.5, 0.75})
    {
      // The nearest point lies off x0 by h/2 at most: compared at its own position.
      const auto [mean, at] = step_mean_near(points, l, x0 * l);
      EXPECT_NEAR(mean, analytic_step_mean(at / l), 0.01) << "h " << h << ", x0 " << x0 << " l";
    }
    // Beyond l the step is seen unsmoothed.
    EXPECT_NEAR(step_mean_near(points, l, -1.3 * l).first, 0.0, 1e-15);
    EXPECT_NEAR(step_mean_near(points, l, 1.3 * l).first, 1.0, 1e-15);
  }
}

TEST(NonlocalFailure, ABandNarrowerThanTheLengthDoesNotFail)
{
  // Two point layers stretched past the limit: the local criterion fails them, the nonlocal
  // one (l = 4 h) sees their mean over l (about 0.4 of the measure) and does not.
  const double h = 0.5e-3;
  EXPECT_GT(failed_half_width(h, 0.0, 2 * h), 0.0);
  EXPECT_EQ(failed_half_width(h, 4 * h, 2 * h), 0.0);
}

TEST(NonlocalFailure, TheFailedZoneIsSetByTheLengthNotTheSpacing)
{
  // A band 6 mm wide at 1.25 times the limit, l = 2 mm: the nonlocal mean passes the limit
  // inside the band up to where the unstrained side weighs 1 - 1/1.25 = 20 % of the kernel,
  // 0.30 l inside the edge by the analytic profile: a failed half-width of 2.4 mm, at point
  // spacings 0.5 and 0.25 mm alike (measured 2.25 and 2.375 mm: the outermost failed point
  // of each lattice). The local criterion fails the whole band at both.
  const double l = 2e-3, width = 6e-3;
  const double coarse = failed_half_width(0.5e-3, l, width);
  const double fine = failed_half_width(0.25e-3, l, width);
  EXPECT_NEAR(coarse, 3e-3 - 0.30 * l, 0.5e-3);
  EXPECT_NEAR(fine, 3e-3 - 0.30 * l, 0.5e-3);
  EXPECT_NEAR(coarse, fine, 0.5e-3);
  EXPECT_NEAR(failed_half_width(0.5e-3, 0.0, width), 3e-3 - 0.25e-3, 1e-9);
}

// A point's neighbour list gives the mean over every point within l (checked against a sum
// over the whole body), and the criterion's cache, kept between steps, is rebuilt when the
// points are re-sorted: the decisions equal a fresh run's.
TEST(NonlocalAverage, NeighbourListsGiveTheMeansAndFollowAReSort)
{
  const double h = 0.5e-3, l = 1.5e-3;
  mpm::Particles points = lattice(h, 3e-3, 2e-3);
  std::vector<double> field(points.size());
  std::vector<char> include(points.size(), 1);
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    const Vector3& x = points.position[p];
    field[p] = std::sin(2e3 * x[0]) + 0.3 * std::cos(3e3 * x[1] * x[2] * 1e3);
    include[p] = (p % 7) != 0;
  }
  const mpm::NonlocalNeighbourhood neighbourhood(points, 0, points.size(), l);
  const std::vector<double> sorted = neighbourhood.in_cell_order(field.data());
  const std::vector<char> sorted_include = neighbourhood.in_cell_order(include.data());
  for (std::size_t p = 0; p < points.size(); p += 13)
  {
    // Against every point of the body, without the binning.
    double sum = 0.0, weights = 0.0;
    for (std::size_t q = 0; q < points.size(); ++q)
    {
      const double r2 = (points.reference_position[q] - points.reference_position[p])
                            .cast<double>()
                            .squaredNorm() / (l * l);
      if (include[q] && r2 < 1.0)
      {
        const double w = (1.0 - r2) * (1.0 - r2) * points.reference_volume[q];
        sum += w * field[q];
        weights += w;
      }
    }
    const std::vector<mpm::NonlocalNeighbour> list = neighbourhood.neighbours(p);
    EXPECT_GT(list.size(), 10u);
    // Single-precision weights and positions: 1e-6 of the field's range.
    EXPECT_NEAR(mpm::NonlocalNeighbourhood::list_mean(list, sorted.data(), sorted_include.data()),
                sum / weights, 1e-6);
  }

  // A band past the shear limit on one side: decide with a cache, re-sort the points (a fixed
  // shuffle), decide again with the same cache, and compare with a fresh cache on the
  // re-sorted points.
  const double stretch = 1.4;
  const mpm::Tensor2 F =
      Eigen::Vector3d(stretch, 1 / std::sqrt(stretch), 1 / std::sqrt(stretch)).asDiagonal();
  for (std::size_t p = 0; p < points.size(); ++p)
    if (std::abs(points.position[p][1]) < 1.6e-3 && points.position[p][0] > 0.0)
      points.deformation_gradient[p] = F;
  const std::unique_ptr<materials::Material> law = gel(l);
  const std::vector<const materials::Material*> bodies{law.get()};
  mpm::NonlocalFailureCache kept;
  mpm::decide_nonlocal_failures(bodies, points, kept);
  std::vector<std::uint32_t> shuffled(points.size());
  std::iota(shuffled.begin(), shuffled.end(), 0u);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
  points.permute(shuffled);
  for (std::uint8_t& flags : points.failure)
    flags = 0;
  mpm::Particles fresh_points = points;
  mpm::decide_nonlocal_failures(bodies, points, kept);
  mpm::NonlocalFailureCache fresh;
  mpm::decide_nonlocal_failures(bodies, fresh_points, fresh);
  std::size_t failing = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    EXPECT_EQ(points.failure[p], fresh_points.failure[p]) << "point " << p;
    failing += (points.failure[p] & materials::matrix_fails_now) != 0;
  }
  EXPECT_GT(failing, 0u);
}

namespace
{
/// Applies the marks the criterion left as the stress update would (tests without a stress
/// update): the failures it decided, total failure where both phases have failed.
void apply_marks(mpm::Particles& points)
{
  for (std::uint8_t& flags : points.failure)
  {
    std::uint8_t failed = flags & materials::total_failure;
    if (flags & materials::matrix_fails_now)
      failed |= materials::matrix_failed;
    if (flags & materials::fibers_fail_now)
      failed |= materials::fiber_failed;
    flags = failed;
  }
}
} // namespace

// The kept cache skips the means that cannot have reached their limit since they were last
// taken (their values' changes within l add up to less than the gap), and gives back the
// lists of points that need no mean, within a budget of kept neighbours. Over steps of a
// growing, uneven strain (matrix and fibers, points turning to debris), its decisions equal
// those of a fresh cache, which takes every mean, at every step, with and without a budget
// too small to keep every list.
TEST(NonlocalFailure, SkippedMeansAndGivenBackListsChangeNoDecision)
{
  const double h = 0.5e-3, l = 1.5e-3;
  mpm::Particles points = lattice(h, 3e-3, 2e-3);
  materials::MaterialParameters m;
  m.model = "transversely isotropic hyperelastic";
  m.tissue.failure.enabled = true;
  m.tissue.failure.matrix_shear_limit = 0.5;
  m.tissue.failure.fiber_stretch_limit = 1.3;
  m.tissue.failure.regularization_length = l;
  const std::unique_ptr<materials::Material> law = materials::create_material(m);
  const std::vector<const materials::Material*> bodies{law.get()};
  mpm::Particles budget_points = points;
  mpm::NonlocalFailureCache kept, budget;
  budget.max_listed_entries = 2000;
  std::size_t means_kept = 0, means_fresh = 0, failed = 0, debris = 0;
  for (int step = 1; step <= 60; ++step)
  {
    const double t = step / 60.0;
    for (mpm::Particles* set : {&points, &budget_points})
      for (std::size_t p = 0; p < set->size(); ++p)
      {
        // Stretch along x (the fibers) growing with time, fastest near y = 0 and x = 1 mm,
        // with an uneven part so that means and their gaps differ from point to point.
        const Vector3 x = set->reference_position[p].cast<double>();
        const double reach = std::exp(-std::pow(x[1] / 1.5e-3, 2) - std::pow((x[0] - 1e-3) / 3e-3, 2));
        const double stretch = 1.0 + 0.8 * t * reach * (1.0 + 0.1 * std::sin(5e3 * x[2] + 3e3 * x[0]));
        set->deformation_gradient[p] =
            Eigen::Vector3d(stretch, 1 / std::sqrt(stretch), 1 / std::sqrt(stretch)).asDiagonal();
      }
    mpm::Particles fresh_points = points;
    mpm::NonlocalFailureCache fresh;
    mpm::decide_nonlocal_failures(bodies, points, kept);
    mpm::decide_nonlocal_failures(bodies, budget_points, budget);
    mpm::decide_nonlocal_failures(bodies, fresh_points, fresh);
    for (std::size_t p = 0; p < points.size(); ++p)
    {
      ASSERT_EQ(points.failure[p], fresh_points.failure[p]) << "step " << step << ", point " << p;
      ASSERT_EQ(budget_points.failure[p], fresh_points.failure[p]) << "step " << step << ", point " << p;
    }
    EXPECT_LE(budget.bodies[0].listed_entries, budget.max_listed_entries);
    means_kept += kept.bodies[0].means_taken;
    means_fresh += fresh.bodies[0].means_taken;
    kept.bodies[0].means_taken = 0;
    apply_marks(points);
    apply_marks(budget_points);
  }
  for (const std::uint8_t flags : points.failure)
  {
    failed += (flags & materials::matrix_failed) != 0;
    debris += flags == materials::total_failure;
  }
  EXPECT_GT(failed, 100u);
  EXPECT_GT(debris, 10u);
  EXPECT_LT(failed, points.size() / 2) << "the strain should stay below the limits somewhere";
  EXPECT_LT(means_kept, means_fresh / 2) << "most means should have been skipped";
}
