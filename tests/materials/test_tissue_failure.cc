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

TEST(TissueFailure, MatrixFailureLeavesTheFibersUniaxialStress)
{
  const TissueParameters p{};
  const TransverselyIsotropicHyperelastic tissue(p);
  const Vector3 a0 = Vector3::UnitX();
  PointState state;
  state.failure = matrix_failed;
  const Tensor2 F = 1.05 * isochoric_uniaxial(1.2, a0); // J > 1: pressure if intact
  PointResponse response;
  tissue.update(F, a0, state, response);
  const TissueStressParts parts = tissue.stress_parts(F, a0, intact);
  EXPECT_GT(max_abs(parts.volumetric), 1e3);
  // Closed form: sigma = f(lambda) / J a (x) a on the total stretch lambda = |F a0|, with no
  // -f/3 I across the fiber (nothing balances it without the matrix) and no tension pressure.
  const Vector3 Fa = F * a0;
  const double lambda = Fa.norm(), J = F.determinant();
  const WeissFiberLaw law(p.c3, p.c4, p.c5, p.lambda_star);
  const Tensor2 expected = law.force(lambda) / J * (Fa / lambda) * (Fa / lambda).transpose();
  EXPECT_LT(max_abs(response.cauchy_stress - expected), 1e-9 * max_abs(expected));
  EXPECT_NEAR(response.cauchy_stress(1, 1), 0.0, 1e-9 * max_abs(expected));
  EXPECT_NEAR(response.energy_density, law.energy(lambda), 1e-9 * law.energy(lambda));
}

TEST(TissueFailure, FailedTissueKeepsItsPressureInCompressionOnly)
{
  const TissueParameters p{};
  const IsotropicHyperelastic tissue(p);
  for (const double J : {0.5, 0.9, 1.1})
  {
    PointState state;
    state.failure = total_failure;
    const Tensor2 F = std::cbrt(J) * isochoric_uniaxial(1.3, Vector3::UnitX());
    PointResponse response;
    tissue.update(F, Vector3::UnitX(), state, response);
    // Debris: sigma = K ln J / J I for J < 1 (never crushed), nothing in tension.
    const double pressure = J < 1.0 ? p.bulk_modulus * std::log(J) / J : 0.0;
    EXPECT_LT(max_abs(response.cauchy_stress - pressure * Tensor2::Identity()),
              1e-9 * p.bulk_modulus)
        << "J = " << J;
    EXPECT_NEAR(response.energy_density,
                J < 1.0 ? 0.5 * p.bulk_modulus * std::log(J) * std::log(J) : 0.0, 1e-9);
    // Its wave is the compression wave (limits the step), none in tension.
    EXPECT_EQ(response.p_wave_modulus > 0.0, J < 1.0) << "J = " << J;
  }
}

TissueParameters paper_rule()
{
  TissueParameters p{};
  p.failure.stress_after_failure = StressAfterFailure::zero;
  return p;
}

TEST(TissueFailure, PaperRuleFailedMatrixCarriesOnlyItsIntactFibers)
{
  // Uintah's TransIsoHyper: a failed matrix drops the matrix and the pressure, in compression
  // too, and the fibers keep their intact (uncoupled) stress; total failure carries nothing.
  const TransverselyIsotropicHyperelastic tissue(paper_rule());
  const Vector3 a0 = Vector3::UnitX();
  for (const double volume : {0.8, 1.05})
  {
    const Tensor2 F = std::cbrt(volume) * isochoric_uniaxial(1.2, a0);
    PointState state;
    state.failure = matrix_failed;
    PointResponse response;
    tissue.update(F, a0, state, response);
    const TissueStressParts intact_parts = tissue.stress_parts(F, a0, intact);
    ASSERT_GT(max_abs(intact_parts.fibers), 1e3);
    EXPECT_LT(max_abs(response.cauchy_stress - intact_parts.fibers),
              1e-12 * max_abs(intact_parts.fibers))
        << "J = " << volume;
    EXPECT_NEAR(response.energy_density, intact_parts.fiber_energy,
                1e-12 * intact_parts.fiber_energy);
    // The fibers' wave alone, on the deviatoric stretch 1.2: no pressure's wave.
    const TissueParameters p = paper_rule();
    const WeissFiberLaw law(p.c3, p.c4, p.c5, p.lambda_star);
    EXPECT_NEAR(response.p_wave_modulus, (law.stiffness(1.2) + law.force(1.2)) / volume,
                1e-9 * response.p_wave_modulus);

    state.failure = total_failure;
    tissue.update(F, a0, state, response);
    EXPECT_EQ(max_abs(response.cauchy_stress), 0.0) << "J = " << volume;
    EXPECT_EQ(response.energy_density, 0.0);
    EXPECT_EQ(response.p_wave_modulus, 0.0);
  }
}

TEST(TissueFailure, PaperRuleReleasesThePressureEnergyAtFailure)
{
  // Compressed and sheared past the limit: the paper's rule releases the matrix's and the
  // pressure's stored energy and keeps the fibers' (the debris rule would keep the pressure's).
  const Vector3 a0 = Vector3::UnitZ();
  const Tensor2 F = 0.9 * isochoric_uniaxial(1.45, a0); // E1 - E3 = 0.57, fibers at 1.305
  const TransverselyIsotropicHyperelastic tissue(paper_rule());
  const TissueStressParts before = tissue.stress_parts(F, a0, intact);
  ASSERT_GT(before.volumetric_energy, 0.1 * before.total_energy());
  PointState state;
  PointResponse response;
  tissue.update(F, a0, state, response);
  ASSERT_EQ(state.failure, matrix_failed);
  EXPECT_NEAR(response.dissipated_density, before.volumetric_energy + before.matrix_energy,
              1e-9 * before.total_energy());
  EXPECT_NEAR(response.energy_density, before.fiber_energy, 1e-9 * before.total_energy());
}

TEST(TissueFailure, FlagsAreIrreversible)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  const Vector3 a0 = Vector3::UnitZ();
  PointState state;
  PointResponse response;
  tissue.update(isochoric_uniaxial(1.35, a0), a0, state, response);
  ASSERT_EQ(state.failure, matrix_failed);
  // Unload to the reference state and stretch the volume: the matrix stays failed, and the
  // failed matrix carries no tension pressure.
  tissue.update(Tensor2::Identity(), a0, state, response);
  EXPECT_EQ(state.failure, matrix_failed);
  tissue.update(1.1 * Tensor2::Identity(), a0, state, response);
  EXPECT_EQ(state.failure, matrix_failed);
  // Only the fibers (along a0 = z) pull; nothing across them.
  EXPECT_EQ(response.cauchy_stress(0, 0), 0.0);
  EXPECT_EQ(response.cauchy_stress(1, 1), 0.0);
  // An intact point under the same dilation carries pressure (the check can fail).
  PointState fresh;
  tissue.update(1.1 * Tensor2::Identity(), a0, fresh, response);
  EXPECT_GT(max_abs(response.cauchy_stress), 1e4);
}

TEST(TissueFailure, DissipatedEnergyIsStoredEnergyAtFailure)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  const Vector3 a0 = Vector3::UnitZ();
  // J < 1: the failed-matrix fibers measure the total stretch J^(1/3) lambda~, lower than the
  // deviatoric one, so less is kept and the release is positive (for J > 1 it can be negative:
  // the change of fiber measure at failure is booked either way).
  const Tensor2 F = 0.995 * isochoric_uniaxial(1.33, a0);
  const TissueStressParts before = tissue.stress_parts(F, a0, intact);
  PointState state;
  PointResponse response;
  tissue.update(F, a0, state, response);
  ASSERT_EQ(state.failure, matrix_failed);
  // Released: everything stored before, minus what the surviving fibers store on the total
  // stretch (J > 1 here: no debris pressure).
  const TissueStressParts after = tissue.stress_parts(F, a0, matrix_failed);
  EXPECT_NEAR(response.dissipated_density, before.total_energy() - after.total_energy(),
              1e-9 * response.dissipated_density);
  EXPECT_GT(response.dissipated_density, 0.0);
  EXPECT_NEAR(response.energy_density, after.total_energy(), 1e-9);
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
