// Tests of the transversely isotropic hyperelastic tissue law and its isotropic variant:
// stress-free reference, objectivity, material symmetry, stress = dW/dF, tangent = dP/dF,
// continuity at lambda*, no fiber compression, closed-form uniaxial and simple shear.
#include "materials/transversely_isotropic_hyperelastic.h"

#include "material_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vulnus::materials
{
namespace
{
using testing::isochoric_uniaxial;
using testing::random_deformation;
using testing::random_rotation;
using testing::random_unit_vector;

TissueParameters no_failure(TissueParameters p = TissueParameters())
{
  p.failure.enabled = false;
  return p;
}

double max_abs(const Tensor2& m)
{
  return m.cwiseAbs().maxCoeff();
}

TEST(TissueLaw, StressFreeAndEnergyFreeAtIdentity)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  const IsotropicHyperelastic isotropic(TissueParameters{});
  for (const Material* material :
       {static_cast<const Material*>(&tissue), static_cast<const Material*>(&isotropic)})
  {
    PointState state;
    PointResponse response;
    material->update(Tensor2::Identity(), Vector3(0.6, 0.0, 0.8), state, response);
    EXPECT_LT(max_abs(response.cauchy_stress), 1e-12);
    EXPECT_LT(std::abs(response.energy_density), 1e-12);
    EXPECT_EQ(state.failure, intact);
    // P-wave modulus of the reference state: K + 4/3 mu0, mu0 = 2 c1.
    EXPECT_NEAR(response.p_wave_modulus, 200e3 + 4.0 / 3.0 * 4.2e3, 1e-6);
  }
}

TEST(TissueLaw, Objectivity)
{
  std::mt19937 rng(1);
  const TransverselyIsotropicHyperelastic tissue(no_failure());
  for (int trial = 0; trial < 50; ++trial)
  {
    const Tensor2 F = random_deformation(rng, 0.3);
    const Tensor2 Q = random_rotation(rng);
    const Vector3 a0 = random_unit_vector(rng);
    PointState s1, s2;
    PointResponse r1, r2;
    tissue.update(F, a0, s1, r1);
    tissue.update(Q * F, a0, s2, r2);
    const Tensor2 rotated = Q * r1.cauchy_stress * Q.transpose();
    EXPECT_LT(max_abs(r2.cauchy_stress - rotated), 1e-9 * (1.0 + max_abs(rotated)));
    EXPECT_NEAR(r2.energy_density, r1.energy_density, 1e-10 * (1.0 + r1.energy_density));
  }
}

TEST(TissueLaw, MaterialSymmetry)
{
  std::mt19937 rng(2);
  const TransverselyIsotropicHyperelastic tissue(no_failure());
  for (int trial = 0; trial < 50; ++trial)
  {
    const Tensor2 F = random_deformation(rng, 0.3);
    const Vector3 a0 = random_unit_vector(rng);
    PointState s;
    PointResponse reference, rotated_fiber, about_fiber;
    tissue.update(F, a0, s, reference);
    // Rotating the reference configuration and the fiber together changes nothing.
    const Tensor2 Q = random_rotation(rng);
    tissue.update(F * Q.transpose(), Q * a0, s, rotated_fiber);
    EXPECT_LT(max_abs(rotated_fiber.cauchy_stress - reference.cauchy_stress),
              1e-9 * (1.0 + max_abs(reference.cauchy_stress)));
    // Transverse isotropy: any rotation about the fiber leaves the response unchanged.
    const Tensor2 R = Eigen::AngleAxisd(0.3 + trial, a0).toRotationMatrix();
    tissue.update(F * R.transpose(), a0, s, about_fiber);
    EXPECT_LT(max_abs(about_fiber.cauchy_stress - reference.cauchy_stress),
              1e-9 * (1.0 + max_abs(reference.cauchy_stress)));
    EXPECT_NEAR(about_fiber.energy_density, reference.energy_density,
                1e-10 * (1.0 + reference.energy_density));
  }
  // A rotation that does not keep the fiber changes the response (the test can fail).
  PointState s;
  PointResponse along, across;
  const Tensor2 F = isochoric_uniaxial(1.2, Vector3::UnitX());
  tissue.update(F, Vector3::UnitX(), s, along);
  tissue.update(F, Vector3::UnitY(), s, across);
  EXPECT_GT(std::abs(along.cauchy_stress(0, 0) - across.cauchy_stress(0, 0)), 100.0);
}

/// Deformations covering the fiber regimes: compression, toe, linear, random.
std::vector<std::pair<Tensor2, Vector3>> sample_states()
{
  std::mt19937 rng(3);
  std::vector<std::pair<Tensor2, Vector3>> states;
  const Vector3 x = Vector3::UnitX();
  for (const double l : {0.85, 1.1, 1.3, 1.55})
    states.emplace_back(
        Eigen::DiagonalMatrix<double, 3>(1.02, 0.97, 1.01) * isochoric_uniaxial(l, x), x);
  for (int i = 0; i < 8; ++i)
    states.emplace_back(random_deformation(rng, 0.25), random_unit_vector(rng));
  return states;
}

TEST(TissueLaw, StressIsDerivativeOfEnergy)
{
  // P = dW/dF by central differences, h = 1e-6: truncation h^2 W'''/6 and round-off
  // eps W / h are both below 1e-6 of the stress scale (W''' ~ c5 e^{c4 (l-1)} c4^2 at most
  // 1e8 Pa here), so tolerance 1e-6 * (|P| + 1 Pa).
  for (const bool with_fibers : {true, false})
  {
    TissueParameters p = no_failure();
    p.c2 = 500.0;
    p.with_fibers = with_fibers;
    const TransverselyIsotropicHyperelastic tissue(p);
    const IsotropicHyperelastic isotropic(p);
    for (const auto& [F, a0] : sample_states())
    {
      auto energy = [&](const Tensor2& G)
      {
        return with_fibers ? tissue.stress_parts(G, a0).total_energy()
                           : isotropic.stress_parts(G, a0).total_energy();
      };
      const Tensor2 P_fd = testing::finite_difference_gradient(energy, F, 1e-6);
      const Tensor2 P = with_fibers ? tissue.first_piola_stress(F, a0, intact)
                                    : isotropic.first_piola_stress(F, a0, intact);
      EXPECT_LT(max_abs(P - P_fd), 1e-6 * (max_abs(P) + 1.0)) << F;
    }
  }
}

TEST(TissueLaw, TangentIsDerivativeOfStress)
{
  // The tangent is exact (dual numbers); the central difference of P with h = 1e-6 has
  // truncation h^2 P'''/6, well below 1e-6 of the tangent scale (K = 2e5 Pa, c5 = 1e5 Pa).
  TissueParameters p = no_failure();
  p.c2 = 300.0;
  const TransverselyIsotropicHyperelastic tissue(p);
  const IsotropicHyperelastic isotropic(p);
  for (const auto& [F, a0] : sample_states())
    for (const std::uint8_t flags : {0, 1, 2})
    {
      PointState state;
      state.failure = flags;
      const Tangent D = tissue.tangent(F, a0, state);
      auto P = [&](const Tensor2& G) { return tissue.first_piola_stress(G, a0, flags); };
      const Tangent D_fd = testing::finite_difference_tangent(P, F, 1e-6);
      EXPECT_LT((D - D_fd).cwiseAbs().maxCoeff(), 1e-6 * (D.cwiseAbs().maxCoeff() + 1.0));
      const Tangent D_iso = isotropic.tangent(F, a0, state);
      auto P_iso = [&](const Tensor2& G) { return isotropic.first_piola_stress(G, a0, flags); };
      EXPECT_LT((D_iso - testing::finite_difference_tangent(P_iso, F, 1e-6)).cwiseAbs().maxCoeff(),
                1e-6 * (D_iso.cwiseAbs().maxCoeff() + 1.0));
    }
}

TEST(TissueLaw, ContinuousAtLambdaStar)
{
  const TransverselyIsotropicHyperelastic tissue(no_failure());
  const Vector3 a0(0.0, 0.6, 0.8);
  const double lambda_star = 1.4;
  const TissueStressParts below =
      tissue.stress_parts(isochoric_uniaxial(lambda_star * (1.0 - 1e-12), a0), a0);
  const TissueStressParts above =
      tissue.stress_parts(isochoric_uniaxial(lambda_star * (1.0 + 1e-12), a0), a0);
  EXPECT_LT(max_abs(below.total() - above.total()), 1e-7 * max_abs(above.total()));
  EXPECT_NEAR(below.total_energy(), above.total_energy(), 1e-9 * above.total_energy());
  EXPECT_GT(max_abs(above.fibers), 1e5); // about 930 kPa of fiber stress at lambda*
}

TEST(TissueLaw, NoFiberStressInFiberCompression)
{
  const TransverselyIsotropicHyperelastic tissue(no_failure());
  const IsotropicHyperelastic isotropic(no_failure());
  const Vector3 a0 = Vector3(1.0, 1.0, 0.0).normalized();
  for (const double l : {0.7, 0.9, 0.999})
  {
    const Tensor2 F = isochoric_uniaxial(l, a0) * 1.05; // with a volume change
    const TissueStressParts parts = tissue.stress_parts(F, a0);
    EXPECT_LT(parts.fiber_stretch, 1.0);
    EXPECT_EQ(max_abs(parts.fibers), 0.0);
    EXPECT_EQ(parts.fiber_energy, 0.0);
    EXPECT_LT(max_abs(parts.total() - isotropic.stress_parts(F, a0).total()), 1e-9);
  }
  // ... and fiber stress in fiber tension (the test can fail).
  EXPECT_GT(max_abs(tissue.stress_parts(isochoric_uniaxial(1.1, a0), a0).fibers), 1.0);
}

TEST(TissueLaw, IsotropicEqualsTissueLawWithoutFiberModuli)
{
  TissueParameters p = no_failure();
  p.c2 = 700.0;
  TissueParameters no_fibers = p;
  no_fibers.c3 = 0.0;
  no_fibers.c5 = 0.0;
  const TransverselyIsotropicHyperelastic tissue(no_fibers);
  const IsotropicHyperelastic isotropic(p);
  EXPECT_FALSE(isotropic.uses_fibers());
  EXPECT_TRUE(tissue.uses_fibers());
  std::mt19937 rng(4);
  for (int trial = 0; trial < 30; ++trial)
  {
    const Tensor2 F = random_deformation(rng, 0.4);
    const Vector3 a0 = random_unit_vector(rng);
    PointState s1, s2;
    PointResponse r1, r2;
    tissue.update(F, a0, s1, r1);
    isotropic.update(F, random_unit_vector(rng), s2, r2); // fiber ignored
    EXPECT_LT(max_abs(r1.cauchy_stress - r2.cauchy_stress),
              1e-9 * (1.0 + max_abs(r1.cauchy_stress)));
    EXPECT_NEAR(r1.energy_density, r2.energy_density, 1e-9 * (1.0 + r1.energy_density));
  }
}

// Closed form, isochoric uniaxial stretch l along the fiber a0 = e_x (incompressible limit,
// the lateral pressure is free): F = diag(l, l^-1/2, l^-1/2), J = 1, so sigma_vol = 0 and
// B~ = diag(l^2, 1/l, 1/l), I1~ = l^2 + 2/l, I2~ = 2 l + 1/l^2. Matrix:
//   sigma_xx - sigma_yy = 2 [(c1 + c2 I1)(l^2 - 1/l) - c2 (l^4 - 1/l^2)]
//                       = 2 (c1 + c2 / l)(l^2 - 1/l)            (Mooney-Rivlin uniaxial)
// Fibers: a = e_x, sigma_f = f(l)(e_x e_x - I/3) adds f(l) to sigma_xx - sigma_yy.
// Everything is deviatoric (trace 0), so sigma_xx = 2/3 d, sigma_yy = sigma_zz = -d/3.
// Energy: c1 (l^2 + 2/l - 3) + c2 (2 l + 1/l^2 - 3) + F2(l).
TEST(TissueLaw, UniaxialStretchAlongFiberClosedForm)
{
  TissueParameters p = no_failure();
  p.c2 = 400.0;
  const TransverselyIsotropicHyperelastic tissue(p);
  const WeissFiberLaw& fibers = tissue.fiber_law();
  for (const double l : {1.05, 1.2, 1.35, 1.5})
  {
    const double c1 = p.c1, c2 = p.c2;
    const double f = l < p.lambda_star ? p.c3 * (std::exp(p.c4 * (l - 1.0)) - 1.0)
                                       : p.c5 * l + fibers.continuity_constant_c6();
    const double d = 2.0 * (c1 + c2 / l) * (l * l - 1.0 / l) + f;
    PointState state;
    PointResponse r;
    tissue.update(isochoric_uniaxial(l, Vector3::UnitX()), Vector3::UnitX(), state, r);
    EXPECT_NEAR(r.cauchy_stress(0, 0), 2.0 / 3.0 * d, 1e-10 * d);
    EXPECT_NEAR(r.cauchy_stress(1, 1), -d / 3.0, 1e-10 * d);
    EXPECT_NEAR(r.cauchy_stress(2, 2), -d / 3.0, 1e-10 * d);
    EXPECT_LT(std::abs(r.cauchy_stress(0, 1)) + std::abs(r.cauchy_stress(1, 2)), 1e-10 * d);
    const double W =
        c1 * (l * l + 2.0 / l - 3.0) + c2 * (2.0 * l + 1.0 / (l * l) - 3.0) + fibers.energy(l);
    EXPECT_NEAR(r.energy_density, W, 1e-10 * W);
  }
}

// Closed form, simple shear F = I + g e_x e_y (J = 1): B = [[1+g^2, g, 0], [g, 1, 0],
// [0, 0, 1]], I1 = 3 + g^2, (B^2)_xy = g (2 + g^2), so the matrix shear stress is
// 2 [(c1 + c2 I1) g - c2 g (2 + g^2)] = 2 (c1 + c2) g, the normal stress difference
// sigma_xx - sigma_yy = 2 (c1 + c2) g^2 (Mooney-Rivlin). Fiber a0 = e_y: F a0 = (g, 1, 0),
// l = sqrt(1 + g^2), a = (g, 1, 0)/l, adds f(l) g / (1 + g^2) to sigma_xy. Fiber a0 = e_z:
// l = 1, no fiber stress.
TEST(TissueLaw, SimpleShearClosedForm)
{
  TissueParameters p = no_failure();
  p.c2 = 250.0;
  const TransverselyIsotropicHyperelastic tissue(p);
  for (const double g : {0.1, 0.4, 0.9})
  {
    Tensor2 F = Tensor2::Identity();
    F(0, 1) = g;
    const double matrix_shear = 2.0 * (p.c1 + p.c2) * g;
    PointState state;
    PointResponse across, along_y;
    tissue.update(F, Vector3::UnitZ(), state, across);
    EXPECT_NEAR(across.cauchy_stress(0, 1), matrix_shear, 1e-10 * matrix_shear);
    EXPECT_NEAR(across.cauchy_stress(0, 0) - across.cauchy_stress(1, 1),
                2.0 * (p.c1 + p.c2) * g * g, 1e-9 * matrix_shear);
    const double l = std::sqrt(1.0 + g * g);
    const double f = l < p.lambda_star ? p.c3 * (std::exp(p.c4 * (l - 1.0)) - 1.0)
                                       : p.c5 * l + tissue.fiber_law().continuity_constant_c6();
    tissue.update(F, Vector3::UnitY(), state, along_y);
    const double expected = matrix_shear + f * g / (1.0 + g * g);
    EXPECT_NEAR(along_y.cauchy_stress(0, 1), expected, 1e-10 * expected);
  }
}

TEST(TissueLaw, WaveModulusPositiveEverywhere)
{
  const TransverselyIsotropicHyperelastic tissue(no_failure());
  const Vector3 a0 = Vector3::UnitX();
  for (const double J : {0.5, 1.0, 2.0, std::exp(1.0), 4.0, 20.0})
    for (const double l : {0.8, 1.0, 1.3, 1.6, 2.5})
    {
      const Tensor2 F = std::cbrt(J) * isochoric_uniaxial(l, a0);
      for (const std::uint8_t flags : {0, 1, 2, 3})
      {
        const double M = tissue.p_wave_modulus(F, a0, flags);
        EXPECT_TRUE(std::isfinite(M));
        // Intact: at least the small-strain shear wave. A failed matrix keeps the bulk wave
        // in compression only; debris in tension (J > 1, fibers slack or failed) has none.
        if (!(flags & matrix_failed))
          EXPECT_GE(M, 4.0 / 3.0 * 4.2e3);
        else if (J < 1.0)
          EXPECT_GE(M, 200e3);
        else
          EXPECT_GE(M, 0.0);
      }
    }
  // Straightened fibers stiffen the wave modulus (c5 ~ 1e5 Pa).
  EXPECT_GT(tissue.p_wave_modulus(isochoric_uniaxial(1.6, a0), a0, intact),
            tissue.p_wave_modulus(isochoric_uniaxial(1.6, a0), a0, fiber_failed) + 1e5);
}

TEST(TissueLaw, InvertedDeformationThrows)
{
  const TransverselyIsotropicHyperelastic tissue(TissueParameters{});
  PointState state;
  PointResponse response;
  const Tensor2 F = Eigen::DiagonalMatrix<double, 3>(1.0, 1.0, -0.5);
  EXPECT_THROW(tissue.update(F, Vector3::UnitX(), state, response), std::runtime_error);
  EXPECT_THROW(tissue.tangent(Tensor2::Zero(), Vector3::UnitX(), state), std::runtime_error);
}
} // namespace
} // namespace vulnus::materials
