// Tests of the elastic-plastic law's gelatin options: Cowper-Symonds rate dependence against
// its steady flow stress in constant-rate tests, the rate-free limits, the consistent tangent
// of the rate-dependent return against finite differences, failure at a plastic strain
// (debris, energy booked), the Hugoniot volumetric law, and bad parameters refused.
#include "materials/material_registry.h"
#include "materials/neo_hookean_plastic.h"

#include "material_test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace vulnus::materials
{
namespace
{
/// 10 % gelatin after Zochowski 2019 (shear modulus, yield, failure strain, K, s), with a
/// Cowper-Symonds law whose constants the test chooses.
ElasticPlasticParameters gelatin(const double rate_constant, const double rate_exponent)
{
  ElasticPlasticParameters p;
  p.bulk_modulus = 2.38e9;
  p.shear_modulus = 0.85e6;
  p.yield_stress = 0.22e6;
  p.hardening_modulus = 0.0;
  p.volumetric_law = VolumetricLawKind::hugoniot;
  p.hugoniot_slope = 2.0;
  p.rate_constant = rate_constant;
  p.rate_exponent = rate_exponent;
  return p;
}

/// Isochoric uniaxial stretch exp(e) along x at a constant log-strain rate over n steps of dt;
/// returns the last response (state updated).
PointResponse stretch_at_constant_rate(const NeoHookeanPlastic& law, const double rate,
                                       const double dt, const int n, PointState& state)
{
  PointResponse r;
  for (int k = 1; k <= n; ++k)
    law.update(testing::isochoric_uniaxial(std::exp(rate * dt * k), Vector3::UnitX()),
               Vector3::UnitX(), state, r, dt);
  return r;
}

TEST(RateDependentPlasticity, SteadyFlowStressIsCowperSymondsAtTheAppliedRate)
{
  // In steady isochoric flow (H = 0) the elastic strain stops changing, so the plastic strain
  // rate equals the applied equivalent rate and the von Mises stress |sigma_xx - sigma_yy|
  // must equal sigma_y (1 + (rate / D)^(1/q)). The return map's plastic increment carries
  // tr(b_e)/3, one plus the elastic strain, so the law is made stiff (mu = 5 GPa): the elastic
  // strain at the largest flow stress (2.4 MPa) is 1.6e-4, and so is the relative error.
  for (const double q : {1.0, 2.5, 6.0})
    for (const double rate : {1.0, 1e2, 1e4})
    {
      ElasticPlasticParameters p = gelatin(1000.0, q);
      p.shear_modulus = 5e9;
      p.bulk_modulus = 10e9;
      const NeoHookeanPlastic law(p);
      PointState state;
      const int n = 3000;
      const PointResponse r = stretch_at_constant_rate(law, rate, 0.6 / rate / n, n, state);
      const double von_mises = r.cauchy_stress(0, 0) - r.cauchy_stress(1, 1);
      const double expected = 0.22e6 * (1.0 + std::pow(rate / 1000.0, 1.0 / q));
      EXPECT_NEAR(von_mises, expected, 3e-4 * expected) << "q " << q << ", rate " << rate;
      EXPECT_NEAR(r.von_mises_over_yield, 1.0, 1e-9);
      EXPECT_NEAR(state.plastic.equivalent_plastic_strain, 0.6, 1e-3);
    }
}

TEST(RateDependentPlasticity, WithoutATimeStepOrARateConstantTheYieldIsRateFree)
{
  ElasticPlasticParameters p = gelatin(0.0, 1.0);
  p.shear_modulus = 50e6; // stiff enough to carry 21 times the yield stress
  const NeoHookeanPlastic rate_free(p);
  p.rate_constant = 100.0;
  const NeoHookeanPlastic viscous(p);
  PointState a, b, c;
  PointResponse ra, rb, rc;
  const double dt = 1e-6;
  for (int k = 1; k <= 200; ++k)
  {
    const Tensor2 F = testing::isochoric_uniaxial(std::exp(0.002 * k), Vector3::UnitX());
    rate_free.update(F, Vector3::UnitX(), a, ra, dt);
    viscous.update(F, Vector3::UnitX(), b, rb); // time step unknown: the rate-free strength
    viscous.update(F, Vector3::UnitX(), c, rc, dt);
  }
  EXPECT_LT((ra.cauchy_stress - rb.cauchy_stress).cwiseAbs().maxCoeff(), 1e-9 * 0.22e6);
  EXPECT_NEAR(ra.cauchy_stress(0, 0) - ra.cauchy_stress(1, 1), 0.22e6, 1e-6 * 0.22e6);
  // At 2000 1/s the viscous law is 21 times stronger.
  EXPECT_GT(rc.cauchy_stress(0, 0) - rc.cauchy_stress(1, 1), 10.0 * 0.22e6);
}

TEST(RateDependentPlasticity, TangentOfTheRateDependentReturnMatchesFiniteDifferences)
{
  // Gelatin's tangent scale is K = 2.4e9 while its deviatoric part is ~1e6: the check runs
  // on a law with K near mu so that the plastic part is not lost in the FD round-off
  // (eps |P| / h with h = 1e-7 is ~1e-9 of the scale); tolerance 1e-6 of the largest entry.
  for (const double q : {1.0, 4.0})
  {
    ElasticPlasticParameters p = gelatin(50.0, q);
    p.bulk_modulus = 3e6;
    p.hardening_modulus = 0.1e6;
    const NeoHookeanPlastic law(p);
    const double dt = 1e-5;
    PointState state;
    PointResponse r;
    std::mt19937 rng(7);
    for (int k = 0; k < 12; ++k)
    {
      // A stretch that yields from the third step on, perturbed by a random 0.5 % deformation.
      const Tensor2 G = testing::isochoric_uniaxial(std::exp(0.04 * k), Vector3::UnitX()) *
                        testing::random_deformation(rng, 0.005);
      const Tangent D = law.tangent(G, Vector3::UnitX(), state, dt);
      auto P = [&](const Tensor2& H)
      {
        return testing::first_piola(law.return_map(H, state.plastic, dt).kirchhoff_stress /
                                        H.determinant(),
                                    H);
      };
      const Tangent D_fd = testing::finite_difference_tangent(P, G, 1e-7);
      EXPECT_LT((D - D_fd).cwiseAbs().maxCoeff(), 1e-6 * D.cwiseAbs().maxCoeff()) << "step " << k;
      law.update(G, Vector3::UnitX(), state, r, dt);
    }
    EXPECT_GT(state.plastic.equivalent_plastic_strain, 0.01); // the steps did flow
  }
}

/// What a point driven to failure in isochoric tension in steps of log strain `step` gives.
struct DrivenToFailure
{
  double failure_strain = -1.0; ///< log strain of the step that failed the point
  double dissipated = 0.0;      ///< sum of dissipated_density
  double work = 0.0;            ///< trapezoidal stress work on the log strain
  PointState state;
  PointResponse last;
};

DrivenToFailure drive_to_failure(const NeoHookeanPlastic& law, const double step)
{
  DrivenToFailure d;
  double previous_von_mises = 0.0;
  for (int k = 1; k <= int(1.0 / step) && d.failure_strain < 0.0; ++k)
  {
    const Tensor2 F = testing::isochoric_uniaxial(std::exp(step * k), Vector3::UnitX());
    law.update(F, Vector3::UnitX(), d.state, d.last, 1e-6);
    // J = 1: the Cauchy stress is the Kirchhoff one, conjugate to the log strain rate.
    const double von_mises = d.last.cauchy_stress(0, 0) - d.last.cauchy_stress(1, 1);
    d.work += 0.5 * step * (von_mises + previous_von_mises);
    d.dissipated += d.last.dissipated_density;
    if (d.state.failure == total_failure)
      d.failure_strain = step * k;
    previous_von_mises = von_mises;
  }
  return d;
}

TEST(RateDependentPlasticity, AtTheFailureStrainThePointBecomesDebrisAndBooksItsEnergy)
{
  ElasticPlasticParameters p = gelatin(0.0, 1.0);
  p.failure_plastic_strain = 0.3;
  const NeoHookeanPlastic law(p);
  // Reached at log strain 0.3 plus the yield strain (0.06 in this law's measure).
  const DrivenToFailure coarse = drive_to_failure(law, 0.002);
  const DrivenToFailure fine = drive_to_failure(law, 0.0005);
  EXPECT_NEAR(coarse.failure_strain, 0.36, 0.02);
  EXPECT_NEAR(fine.failure_strain, coarse.failure_strain, 0.003);
  // Debris at J = 1 (to round-off) carries and stores nothing.
  EXPECT_LT(fine.last.cauchy_stress.cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_LT(fine.last.energy_density, 1e-9);
  // Everything the stress did went into dissipation (plastic, and the elastic energy released
  // at failure). The trapezoid misses half the last step, where the stress drops to zero, and
  // differs from the elastic trial's path (which the algorithm's energy follows) by a term of
  // the step's order: the gap shrinks with the step, and at 0.0005 it is below 0.3 %.
  auto gap = [](const DrivenToFailure& d, const double step)
  { return std::abs(d.dissipated - d.work - 0.5 * step * 0.22e6); };
  EXPECT_LT(gap(fine, 0.0005), 0.4 * gap(coarse, 0.002));
  EXPECT_LT(gap(fine, 0.0005), 3e-3 * fine.work);

  PointState state = fine.state;
  PointResponse r;
  // Debris keeps the Hugoniot pressure in compression and nothing in tension.
  const double J = 0.95;
  law.update(std::cbrt(J) * Tensor2::Identity(), Vector3::UnitX(), state, r, 1e-6);
  const double eta = 1.0 - J, w = 1.0 - 2.0 * eta;
  EXPECT_NEAR(-r.cauchy_stress(0, 0), 2.38e9 * eta / (w * w), 1e-9 * 2.38e9);
  EXPECT_NEAR(r.cauchy_stress(0, 1), 0.0, 1e-6);
  EXPECT_GT(r.p_wave_modulus, 2.38e9);
  law.update(std::cbrt(1.05) * Tensor2::Identity(), Vector3::UnitX(), state, r, 1e-6);
  EXPECT_EQ(r.cauchy_stress.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(r.p_wave_modulus, 0.0);
  EXPECT_EQ(state.failure, total_failure);
  // The debris tangent is the volumetric one in compression.
  const Tangent D = law.tangent(std::cbrt(J) * Tensor2::Identity(), Vector3::UnitX(), state, 1e-6);
  auto P = [&](const Tensor2& H)
  {
    PointState copy = state;
    PointResponse response;
    law.update(H, Vector3::UnitX(), copy, response, 1e-6);
    return testing::first_piola(response.cauchy_stress, H);
  };
  const Tangent D_fd = testing::finite_difference_tangent(P, std::cbrt(J) * Tensor2::Identity(), 1e-7);
  EXPECT_LT((D - D_fd).cwiseAbs().maxCoeff(), 1e-6 * D.cwiseAbs().maxCoeff());
}

TEST(RateDependentPlasticity, ElasticPlasticPressureFollowsTheChosenVolumetricLaw)
{
  for (const VolumetricLawKind kind :
       {VolumetricLawKind::simo_hughes, VolumetricLawKind::logarithmic, VolumetricLawKind::hugoniot})
  {
    ElasticPlasticParameters p = gelatin(0.0, 1.0);
    p.volumetric_law = kind;
    const NeoHookeanPlastic law(p);
    for (const double J : {0.8, 0.97, 1.0, 1.04})
    {
      PointState state;
      PointResponse r;
      law.update(std::cbrt(J) * Tensor2::Identity(), Vector3::UnitX(), state, r);
      const double K = p.bulk_modulus;
      const double eta = 1.0 - J, w = 1.0 - 2.0 * eta;
      const double expected_pressure =
          kind == VolumetricLawKind::simo_hughes ? -0.5 * K * (J - 1.0 / J)
          : (kind == VolumetricLawKind::hugoniot && J < 1.0) ? K * eta / (w * w)
                                                               : -K * std::log(J) / J;
      EXPECT_NEAR(-r.cauchy_stress(0, 0), expected_pressure, 1e-9 * K) << J;
    }
  }
}

TEST(RateDependentPlasticity, BadRateAndFailureParametersAreRefusedByName)
{
  MaterialParameters parameters;
  parameters.model = "elastic plastic";
  parameters.elastic_plastic = gelatin(-1.0, 0.0);
  parameters.elastic_plastic.failure_plastic_strain = -0.5;
  parameters.elastic_plastic.hugoniot_slope = 9.0;
  std::vector<std::string> names;
  for (const ParameterProblem& problem : check_parameters(parameters))
    names.push_back(problem.parameters.front());
  for (const char* entry : {"Rate constant", "Rate exponent", "Failure plastic strain", "Hugoniot slope"})
    EXPECT_NE(std::find(names.begin(), names.end(), entry), names.end()) << entry;
  EXPECT_TRUE(check_parameters(MaterialParameters{"elastic plastic", {}, gelatin(100.0, 2.0)}).empty());
}
} // namespace
} // namespace vulnus::materials
