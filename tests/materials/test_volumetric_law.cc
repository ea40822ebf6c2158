// Tests of the tissue's volumetric laws: the Hugoniot law's pressure against the
// Rankine-Hugoniot jump of a shock with Us = c0 + s up, its energy, stress and tangent as
// derivatives of each other on every branch, and its agreement with the logarithmic law
// near J = 1.
#include "materials/transversely_isotropic_hyperelastic.h"
#include "materials/volumetric_law.h"

#include "material_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vulnus::materials
{
namespace
{
TissueParameters water_stiff(const VolumetricLawKind law, const double s = 2.0)
{
  TissueParameters p;
  p.bulk_modulus = 2.2e9;
  p.volumetric_law = law;
  p.hugoniot_slope = s;
  p.failure.enabled = false;
  return p;
}

double pressure(const TransverselyIsotropicHyperelastic& tissue, const double J)
{
  const Tensor2 F = std::cbrt(J) * Tensor2::Identity();
  return -tissue.stress_parts(F, Vector3(1.0, 0.0, 0.0)).total().trace() / 3.0;
}

TEST(VolumetricLaw, HugoniotPressureIsTheShockJumpOfUsEqualsC0PlusSUp)
{
  // A shock running at Us = c0 + s up into tissue at rest: mass and momentum across it give
  // J = 1 - up / Us and p = rho0 Us up. The law must give that p at that J, for any up
  // (checked to 500 m/s, J = 0.72 for s = 2, beyond the bullet's 150 m/s).
  const double rho0 = 1060.0;
  for (const double s : {1.0, 1.79, 2.0})
  {
    const TissueParameters p = water_stiff(VolumetricLawKind::hugoniot, s);
    const TransverselyIsotropicHyperelastic tissue(p);
    const double c0 = std::sqrt(p.bulk_modulus / rho0);
    for (const double up : {1.0, 20.0, 75.0, 150.0, 300.0, 500.0})
    {
      const double Us = c0 + s * up;
      const double J = 1.0 - up / Us;
      EXPECT_NEAR(pressure(tissue, J), rho0 * Us * up, 1e-9 * rho0 * Us * up) << s << " " << up;
    }
  }
}

TEST(VolumetricLaw, HugoniotIsStifferThanTheLogarithmicLawInCompressionOnly)
{
  const TransverselyIsotropicHyperelastic hugoniot(water_stiff(VolumetricLawKind::hugoniot));
  const TransverselyIsotropicHyperelastic logarithmic(water_stiff(VolumetricLawKind::logarithmic));
  // Near J = 1 both are K (1 - J): the first two terms of p agree to O(eta^2).
  for (const double eta : {1e-4, 1e-3})
    EXPECT_NEAR(pressure(hugoniot, 1.0 - eta) / pressure(logarithmic, 1.0 - eta), 1.0,
                4.0 * eta);
  // At the bullet's nose (eta about 0.1) the Hugoniot is markedly stiffer: K eta / (1 - 2 eta)^2
  // against -K ln(1 - eta) / (1 - eta): 1.5625 K eta against 1.1707 K eta.
  EXPECT_NEAR(pressure(hugoniot, 0.9) / pressure(logarithmic, 0.9), 1.5625 / 1.17067, 1e-4);
  // Tension is the logarithmic law's.
  for (const double J : {1.01, 1.2, 2.0})
    EXPECT_DOUBLE_EQ(pressure(hugoniot, J), pressure(logarithmic, J));
}

TEST(VolumetricLaw, EnergyStressAndTangentAreDerivativesOnEveryBranch)
{
  // U' = -p and J U'' = K_t by central differences across the logarithmic tension branch,
  // the Hugoniot branch and its linear continuation below J_floor = 1 - 0.75 / s = 0.625;
  // h = 1e-6 in J, tolerance 1e-6 of the scale (U''' is at most about 1e3 K there).
  TissueParameters p = water_stiff(VolumetricLawKind::hugoniot);
  const VolumetricLaw law(p);
  const double K = p.bulk_modulus;
  const double h = 1e-6;
  for (const double J : {0.3, 0.6, 0.624, 0.626, 0.7, 0.9, 0.999, 1.001, 1.3})
  {
    const double U_prime = law.kirchhoff_pressure_term(J) / J;
    EXPECT_NEAR((law.energy(J + h) - law.energy(J - h)) / (2 * h), U_prime,
                1e-6 * (std::abs(U_prime) + K))
        << J;
    const double U_second =
        (law.kirchhoff_pressure_term(J + h) / (J + h) - law.kirchhoff_pressure_term(J - h) / (J - h)) /
        (2 * h);
    EXPECT_NEAR(law.tangent_bulk_modulus(J), J * U_second, 1e-5 * (std::abs(J * U_second) + K))
        << J;
  }
  // U, U' and U'' continuous at J = 1 (all three equal the logarithmic law's there: 0, 0, K).
  EXPECT_NEAR(law.energy(1.0 - 1e-9), 0.0, 1e-6);
  EXPECT_NEAR(law.tangent_bulk_modulus(1.0 - 1e-9), K, 1e-6 * K);
  EXPECT_NEAR(law.tangent_bulk_modulus(1.0 + 1e-9), K, 1e-6 * K);
  // Below the floor the pressure stays finite and keeps rising linearly: no singularity at
  // J = 1 - 1/s = 0.5.
  EXPECT_TRUE(std::isfinite(law.kirchhoff_pressure_term(0.5)));
  EXPECT_LT(law.kirchhoff_pressure_term(0.4) / 0.4, law.kirchhoff_pressure_term(0.5) / 0.5);
}

TEST(VolumetricLaw, TissueStressAndTangentWithTheHugoniotLaw)
{
  // The whole tissue law with the Hugoniot volume: P = dW/dF and the exact tangent = dP/dF by
  // central differences (h = 1e-7 in F; the volumetric part dominates at K = 2.2 GPa), in
  // compressed and stretched states, intact and with a failed matrix (debris in compression;
  // J = 1 itself is left out: debris loses its stiffness there, a kink of the failure rule).
  std::mt19937 rng(5);
  const TissueParameters p = water_stiff(VolumetricLawKind::hugoniot);
  const TransverselyIsotropicHyperelastic tissue(p);
  for (int trial = 0; trial < 12; ++trial)
  {
    const double J = 0.613 + 0.05 * trial;
    const Tensor2 G = testing::random_deformation(rng, 0.1);
    const Tensor2 F = std::cbrt(J / G.determinant()) * G;
    const Vector3 a0 = testing::random_unit_vector(rng);
    auto energy = [&](const Tensor2& G) { return tissue.stress_parts(G, a0).total_energy(); };
    const Tensor2 P = tissue.first_piola_stress(F, a0, intact);
    const Tensor2 P_fd = testing::finite_difference_gradient(energy, F, 1e-7);
    EXPECT_LT((P - P_fd).cwiseAbs().maxCoeff(), 1e-6 * (P.cwiseAbs().maxCoeff() + 1.0)) << J;
    for (const std::uint8_t flags : {std::uint8_t(0), std::uint8_t(1)})
    {
      PointState state;
      state.failure = flags;
      const Tangent D = tissue.tangent(F, a0, state);
      auto stress = [&](const Tensor2& G) { return tissue.first_piola_stress(G, a0, flags); };
      const Tangent D_fd = testing::finite_difference_tangent(stress, F, 1e-7);
      EXPECT_LT((D - D_fd).cwiseAbs().maxCoeff(), 1e-5 * (D.cwiseAbs().maxCoeff() + 1.0)) << J;
    }
  }
}

TEST(VolumetricLaw, WaveModulusFollowsTheHugoniotStiffening)
{
  // The time step must see the stiffer compressed state: M includes J U'' = J K (1 + s eta)
  // / (1 - s eta)^3, 2.6 K at eta = 0.1 for s = 2 (the logarithmic law: K (1 - ln J) / J).
  const TransverselyIsotropicHyperelastic tissue(water_stiff(VolumetricLawKind::hugoniot));
  const double K = 2.2e9;
  const double J = 0.9;
  PointState state;
  PointResponse response;
  tissue.update(std::cbrt(J) * Tensor2::Identity(), Vector3(1.0, 0.0, 0.0), state, response);
  const double expected = J * K * 1.2 / (0.8 * 0.8 * 0.8);
  EXPECT_NEAR(response.p_wave_modulus, expected + 4.0 / 3.0 * 2.0 * 2100.0 / J, 1e-9 * expected);
}
} // namespace
} // namespace vulnus::materials
