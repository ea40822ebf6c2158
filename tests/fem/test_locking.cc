// Volumetric locking and its cure in both discretisations: the divergence-free shear mode of
// a square at bulk:shear 1e4 (benchmarks/locking/shear_mode.h), whose analytic period does
// not depend on the bulk modulus. With each point's own J, MPM and Q1 lock (the square rings
// far too fast); with the cell's mean J (F-bar) both ring at the analytic period, closer on
// the finer grid. The far field explicit and implicit (Newmark, Newton on the F-bar tangent),
// and explicit with one point per cell and hourglass control. And the thick cylinder against
// Lame's solution, at 1e4 and 1e6.
#include "benchmarks/locking/lame_cylinder.h"
#include "benchmarks/locking/shear_mode.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace vulnus;
using verification::ShearModeResult;

namespace
{
void expect_locked_then_cured(const char* name, const ShearModeResult& locked,
                              const ShearModeResult& coarse, const ShearModeResult& fine)
{
  std::cout << name << " period / analytic: own J " << locked.period_ratio << ", cell J (10 cells) "
            << coarse.period_ratio << ", cell J (20 cells) " << fine.period_ratio << std::endl;
  EXPECT_LT(locked.period_ratio, 0.7) << name; // measured 0.16-0.18
  EXPECT_NEAR(coarse.period_ratio, 1.0, 0.05) << name;
  EXPECT_NEAR(fine.period_ratio, 1.0, 0.03) << name;
  EXPECT_LT(std::abs(fine.period_ratio - 1.0), std::abs(coarse.period_ratio - 1.0)) << name;
}
} // namespace

TEST(Locking, MpmShearModeKeepsItsPeriodWithCellAveragedVolume)
{
  expect_locked_then_cured("MPM", verification::mpm_shear_mode(10, 1e4, false),
                           verification::mpm_shear_mode(10, 1e4, true),
                           verification::mpm_shear_mode(20, 1e4, true));
}

TEST(Locking, FarFieldShearModeKeepsItsPeriodWithFBar)
{
  for (const fem::TimeIntegrator integrator :
       {fem::TimeIntegrator::central_difference, fem::TimeIntegrator::newmark})
    expect_locked_then_cured(integrator == fem::TimeIntegrator::newmark ? "FE Newmark"
                                                                        : "FE explicit",
                             verification::fe_shear_mode(10, 1e4, false, integrator),
                             verification::fe_shear_mode(10, 1e4, true, integrator),
                             verification::fe_shear_mode(20, 1e4, true, integrator));
}

// One point per cell has one volumetric constraint per cell by construction, so it does not
// lock with or without the cell's mean J; with its hourglass stiffness it rings at the full
// F-bar element's period (the same element at small strain on box cells, fem/hourglass.h;
// measured 1.01172 both on 10 cells).
TEST(Locking, FarFieldOnePointRingsAsTheFullFBarElement)
{
  const ShearModeResult one =
      verification::fe_shear_mode(10, 1e4, false, fem::TimeIntegrator::central_difference, true);
  const ShearModeResult full =
      verification::fe_shear_mode(10, 1e4, true, fem::TimeIntegrator::central_difference);
  std::cout << "FE one point period / analytic " << one.period_ratio << ", full F-bar "
            << full.period_ratio << std::endl;
  EXPECT_NEAR(one.period_ratio, 1.0, 0.05);
  EXPECT_NEAR(one.period_ratio, full.period_ratio, 1e-4);
}

// The thick cylinder pushed from inside (benchmarks/locking/lame_cylinder.h): its pressure is
// uniform and finite however stiff the bulk. With each point's own J, Q1 overestimates it by
// orders of magnitude (measured 9.1 times on 8 cells at 1e4, 809 times at 1e6); with F-bar the
// pressure, the stresses and the displacement converge at second order to Lame's solution,
// with the same stress errors at 1e4 and 1e6.
TEST(Locking, FarFieldLameCylinderConvergesWithFBarAndLocksWithout)
{
  for (const double ratio : {1e4, 1e6})
  {
    const verification::LameResult locked = verification::lame_cylinder(8, ratio, false);
    const verification::LameResult coarse = verification::lame_cylinder(4, ratio, true);
    const verification::LameResult fine = verification::lame_cylinder(8, ratio, true);
    std::cout << "K/mu " << ratio << ": Q1 own J p/p_exact "
              << locked.mean_pressure / locked.exact_pressure << "; F-bar pressure error "
              << coarse.pressure_error << " -> " << fine.pressure_error << ", displacement error "
              << coarse.displacement_error << " -> " << fine.displacement_error << ", p/p_exact "
              << fine.mean_pressure / fine.exact_pressure << std::endl;
    EXPECT_GT(locked.mean_pressure / locked.exact_pressure, 5.0) << ratio;
    // Measured 2.5e-3 -> 6.5e-4 (order 1.95) for the pressure and the radial stress, 1.9 for
    // the displacement; order above 1.6 is second order with margin.
    EXPECT_LT(fine.pressure_error, 1e-3) << ratio;
    EXPECT_LT(fine.radial_stress_error, 1e-3) << ratio;
    EXPECT_GT(std::log2(coarse.pressure_error / fine.pressure_error), 1.6) << ratio;
    EXPECT_GT(std::log2(coarse.radial_stress_error / fine.radial_stress_error), 1.6) << ratio;
    EXPECT_GT(std::log2(coarse.displacement_error / fine.displacement_error), 1.6) << ratio;
    EXPECT_NEAR(fine.mean_pressure / fine.exact_pressure, 1.0, 5e-3) << ratio; // 1.0017
  }
}
