// Tests of the two-surface failure of the tissue law: thresholds crossed along paths, the
// right parts vanish, flags are irreversible, total failure, shear measures, dissipation.
#include "materials/transversely_isotropic_hyperelastic.h"
#include "materials/two_surface_failure.h"

#include "material_test_helpers.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>

namespace vulnus::materials
{
namespace
{
using testing::isochoric_uniaxial;

double max_abs(const Tensor2& m)
{
  return m.cwiseAbs().maxCoeff();
}

/// Drives isochoric uniaxial stretch along a0 from 1 to l_max in n steps; returns the
/// stretch of the first step at which `flag_bit` is set (0 if never).
double stretch_at_first_flag(const Material& material, const std::uint8_t flag_bit,
                             const double l_max, const int n, PointState& state)
{
  const Vector3 a0 = Vector3(0.0, 0.0, 1.0);
  for (int k = 0; k <= n; ++k)
  {
    const double l = 1.0 + (l_max - 1.0) * k / n;
    PointResponse response;
    material.update(isochoric_uniaxial(l, a0), a0, state, response);
    if (state.failure & flag_bit)
      return l;
  }
  return 0.0;
}

TEST(TissueFailure, MatrixFailsAtRootOfCubicAlongFiber)
{
  // E1 - E3 = (l^2 - 1/l)/2 > 0.5 <=> l^3 - l - 1 > 0: l = 1.324717957244746 (plastic number).
  const double root = 1.324717957244746;
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  PointState state;
  const double step = 1e-5;
  const double l = stretch_at_first_flag(tissue, matrix_failed, 1.5, 50000, state);
  EXPECT_GT(l, root);
  EXPECT_LE(l - step, root + 1e-12);
  EXPECT_EQ(state.failure, matrix_failed); // fibers (limit 1.4) still intact
}

TEST(TissueFailure, OtherShearMeasures)
{
  // (E1-E3)/2 = (l^2 - 1/l)/4 > 0.5 <=> (l + 1)(l^2 - l - 1) > 0: golden ratio 1.618...
  // ln(l1/l3) = 1.5 ln l > 0.5 <=> l > e^{1/3}.
  struct Case
  {
    ShearMeasure measure;
    double root;
  };
  for (const Case c : {Case{ShearMeasure::half_principal_green_difference, 1.6180339887498949},
                       Case{ShearMeasure::log_stretch_ratio, std::exp(1.0 / 3.0)}})
  {
    TissueParameters p;
    p.failure.shear_measure = c.measure;
    p.failure.fiber_stretch_limit = 5.0;
    const IsotropicHyperelastic isotropic(p);
    PointState state;
    const double l = stretch_at_first_flag(isotropic, matrix_failed, 1.8, 80000, state);
    EXPECT_GT(l, c.root);
    EXPECT_LE(l - 1e-5, c.root + 1e-12);
  }
}

TEST(TissueFailure, IsotropicMatrixFailureIsTotalFailure)
{
  // Without fibers nothing carries stress once the matrix has failed: flag 3, zero stress.
  const IsotropicHyperelastic isotropic(TissueParameters{});
  PointState state;
  const double l = stretch_at_first_flag(isotropic, matrix_failed, 1.5, 50000, state);
  EXPECT_GT(l, 1.324717957244746);
  EXPECT_EQ(state.failure, matrix_failed | fiber_failed);
  PointResponse response;
  isotropic.update(isochoric_uniaxial(1.6, Vector3(0.0, 0.0, 1.0)), Vector3(0.0, 0.0, 1.0), state,
                   response);
  EXPECT_EQ(response.cauchy_stress.norm(), 0.0);
}

TEST(TissueFailure, FibersFailAtStretchLimit)
{
  TissueParameters p;
  p.failure.matrix_shear_limit = 10.0; // keep the matrix intact
  const TransverselyIsotropicHyperelastic tissue(p);
  PointState state;
  const double l = stretch_at_first_flag(tissue, fiber_failed, 1.5, 50000, state);
  EXPECT_GT(l, 1.4);
  EXPECT_LE(l - 1e-5, 1.4 + 1e-12);
  EXPECT_EQ(state.failure, fiber_failed);

  // Fiber stress gone, matrix and volumetric stress kept.
  const Vector3 a0 = Vector3::UnitZ();
  const Tensor2 F = 1.01 * isochoric_uniaxial(1.45, a0);
  PointResponse response;
  tissue.update(F, a0, state, response);
  const TissueStressParts intact_parts = tissue.stress_parts(F, a0, intact);
  EXPECT_LT(max_abs(response.cauchy_stress - intact_parts.volumetric - intact_parts.matrix),
            1e-9 * max_abs(intact_parts.matrix));
  EXPECT_NEAR(response.energy_density, intact_parts.volumetric_energy + intact_parts.matrix_energy,
              1e-9);
  EXPECT_GT(max_abs(intact_parts.fibers), 1e5);
}

TEST(TissueFailure, MatrixFailureRemovesMatrixAndPressureKeepsFibers)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  const Vector3 a0 = Vector3::UnitX();
  PointState state;
  state.failure = matrix_failed;
  const Tensor2 F = 1.05 * isochoric_uniaxial(1.2, a0); // J > 1: pressure if intact
  PointResponse response;
  tissue.update(F, a0, state, response);
  const TissueStressParts parts = tissue.stress_parts(F, a0, intact);
  EXPECT_GT(max_abs(parts.volumetric), 1e3);
  EXPECT_LT(max_abs(response.cauchy_stress - parts.fibers), 1e-9 * max_abs(parts.fibers));
  EXPECT_NEAR(response.energy_density, parts.fiber_energy, 1e-9);
}

TEST(TissueFailure, BothGiveTotalFailureAndZeroStress)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  PointState state;
  // Default limits: matrix at 1.3247, then fibers at 1.4.
  EXPECT_GT(stretch_at_first_flag(tissue, fiber_failed, 1.6, 600, state), 1.4);
  EXPECT_EQ(state.failure, total_failure);
  PointResponse response;
  const Vector3 a0 = Vector3::UnitZ();
  tissue.update(1.1 * isochoric_uniaxial(1.5, a0), a0, state, response);
  EXPECT_EQ(max_abs(response.cauchy_stress), 0.0);
  EXPECT_EQ(response.energy_density, 0.0);
  EXPECT_GT(response.p_wave_modulus, 0.0); // still limits the time step
}

TEST(TissueFailure, FlagsAreIrreversible)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  const Vector3 a0 = Vector3::UnitZ();
  PointState state;
  PointResponse response;
  tissue.update(isochoric_uniaxial(1.35, a0), a0, state, response);
  ASSERT_EQ(state.failure, matrix_failed);
  // Unload to the reference state and compress: the matrix stays failed, no pressure.
  tissue.update(Tensor2::Identity(), a0, state, response);
  EXPECT_EQ(state.failure, matrix_failed);
  tissue.update(0.9 * Tensor2::Identity(), a0, state, response);
  EXPECT_EQ(state.failure, matrix_failed);
  EXPECT_EQ(max_abs(response.cauchy_stress), 0.0);
  // An intact point under the same compression carries pressure (the check can fail).
  PointState fresh;
  tissue.update(0.9 * Tensor2::Identity(), a0, fresh, response);
  EXPECT_GT(max_abs(response.cauchy_stress), 1e4);
}

TEST(TissueFailure, DissipatedEnergyIsStoredEnergyAtFailure)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  const Vector3 a0 = Vector3::UnitZ();
  const Tensor2 F = 1.02 * isochoric_uniaxial(1.33, a0);
  const TissueStressParts before = tissue.stress_parts(F, a0, intact);
  PointState state;
  PointResponse response;
  tissue.update(F, a0, state, response);
  ASSERT_EQ(state.failure, matrix_failed);
  EXPECT_NEAR(response.dissipated_density, before.volumetric_energy + before.matrix_energy,
              1e-9 * response.dissipated_density);
  EXPECT_GT(response.dissipated_density, 0.0);
  EXPECT_NEAR(response.energy_density, before.fiber_energy, 1e-9);
  // Nothing more is released in the next update.
  tissue.update(F, a0, state, response);
  EXPECT_EQ(response.dissipated_density, 0.0);
}

TEST(TissueFailure, DisabledFailureNeverFlags)
{
  TissueParameters p;
  p.failure.enabled = false;
  const TransverselyIsotropicHyperelastic tissue(p);
  PointState state;
  EXPECT_EQ(stretch_at_first_flag(tissue, total_failure, 2.0, 100, state), 0.0);
  EXPECT_EQ(state.failure, intact);
}

TEST(TissueFailure, DeviatorBoundsDecideLikeEigenvalues)
{
  // The matrix check skips eigenvalues when |dev B| decides; compare with the brute force.
  std::mt19937 rng(5);
  for (const ShearMeasure measure :
       {ShearMeasure::principal_green_difference, ShearMeasure::half_principal_green_difference,
        ShearMeasure::log_stretch_ratio})
  {
    FailureParameters p;
    p.shear_measure = measure;
    int n_failed = 0;
    for (int trial = 0; trial < 4000; ++trial)
    {
      const Tensor2 F = testing::random_deformation(rng, 0.05 + 0.5 * (trial % 10) / 10.0);
      const Eigen::SelfAdjointEigenSolver<Tensor2> solver(F.transpose() * F);
      const Eigen::Vector3d ascending = solver.eigenvalues();
      const double measure_value =
          matrix_shear_measure(measure, Vector3(ascending[2], ascending[1], ascending[0]));
      if (std::abs(measure_value - p.matrix_shear_limit) < 1e-12)
        continue;
      const bool expected = measure_value > p.matrix_shear_limit;
      n_failed += expected;
      EXPECT_EQ(updated_failure_flags(p, F, Vector3::UnitX(), false, intact),
                expected ? matrix_failed : intact);
    }
    EXPECT_GT(n_failed, 100);
    EXPECT_LT(n_failed, 3900);
  }
}

TEST(TissueFailure, FlagUpdateChecksOnlyIntactPhases)
{
  FailureParameters p;
  const Tensor2 F = isochoric_uniaxial(1.5, Vector3::UnitX());
  EXPECT_EQ(updated_failure_flags(p, F, Vector3::UnitX(), true, intact), total_failure);
  EXPECT_EQ(updated_failure_flags(p, F, Vector3::UnitX(), false, intact), matrix_failed);
  EXPECT_EQ(updated_failure_flags(p, Tensor2::Identity(), Vector3::UnitX(), true, fiber_failed),
            fiber_failed);
  p.enabled = false;
  EXPECT_EQ(updated_failure_flags(p, F, Vector3::UnitX(), true, matrix_failed), matrix_failed);
}
} // namespace
} // namespace vulnus::materials
