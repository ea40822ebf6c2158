// Plain parameter structs of the material models, filled by the deck reader (app/) or by
// tests; the defaults are the paper's values (docs/DESIGN.md sections 2-3). SI units.
#pragma once

#include <string>
#include <vector>

namespace vulnus::materials
{
/// Measure of the maximum shear strain compared with the matrix failure limit.
enum class ShearMeasure
{
  principal_green_difference,      ///< E1 - E3 (Uintah's convention, the default)
  half_principal_green_difference, ///< (E1 - E3) / 2, the tensorial shear strain
  log_stretch_ratio                ///< ln(l1 / l3) of the principal stretches
};

/// A law's volumetric energy (materials/volumetric_law.h).
enum class VolumetricLawKind
{
  logarithmic, ///< U = K/2 (ln J)^2 (the paper's tissue)
  hugoniot,    ///< compression on the linear shock Hugoniot Us = c0 + s up, K = rho0 c0^2
  simo_hughes  ///< U = K/2 [(J^2 - 1)/2 - ln J] (the elastic-plastic bullet's)
};

/// What a failed tissue point carries (docs/DESIGN.md section 3, docs/uintah_side_by_side.md).
enum class StressAfterFailure
{
  debris, ///< failed matrix: fibers f a (x) a on the total stretch, pressure in compression only
  zero    ///< the paper's and Uintah's rule: failed matrix annuls matrix and pressure, total all
};

/// Two-surface failure (paper eqs. 5-6).
struct FailureParameters
{
  bool enabled = true;
  ShearMeasure shear_measure = ShearMeasure::principal_green_difference;
  double matrix_shear_limit = 0.5;  ///< gamma_crit, > 0
  double fiber_stretch_limit = 1.4; ///< lambda_crit, > 1
  /// Nonlocal regularization: radius l (m) over which the MPM points average both failure
  /// measures before comparing them with the limits; 0: the paper's local criterion.
  double regularization_length = 0.0;
  StressAfterFailure stress_after_failure = StressAfterFailure::debris;
};

/// Transversely isotropic hyperelastic tissue (Weiss 1996, uncoupled). With
/// with_fibers = false it is the isotropic Mooney-Rivlin variant (c3 = c5 = 0, no fiber work).
struct TissueParameters
{
  bool with_fibers = true;
  double c1 = 2.1e3;             ///< Pa
  double c2 = 0.0;               ///< Pa
  double c3 = 0.14e3;            ///< Pa, toe-region scale
  double c4 = 22.0;              ///< -, rate of uncrimping
  double c5 = 100.0e3;           ///< Pa, modulus of straightened fibers
  double lambda_star = 1.4;      ///< fiber stretch where fibers straighten, >= 1
  double bulk_modulus = 200.0e3; ///< Pa, U''(1) of the volumetric law
  VolumetricLawKind volumetric_law = VolumetricLawKind::logarithmic;
  double hugoniot_slope = 2.0;   ///< s of Us = c0 + s up (Hugoniot law only)
  FailureParameters failure;
};

/// Neo-Hookean elasticity with J2 plasticity and linear isotropic hardening (Simo-Hughes box 9.1).
struct ElasticPlasticParameters
{
  double bulk_modulus = 117.0e9;     ///< Pa
  double shear_modulus = 53.8e9;     ///< Pa
  double yield_stress = 422.6e6;     ///< Pa
  double hardening_modulus = 53.8e6; ///< Pa, linear isotropic hardening
  VolumetricLawKind volumetric_law = VolumetricLawKind::simo_hughes;
  double hugoniot_slope = 2.0; ///< s of Us = c0 + s up (Hugoniot law only)
  /// Cowper-Symonds rate dependence of the flow stress, (sigma_y + H alpha) (1 + (alpha_dot /
  /// D)^(1/q)) with alpha_dot the equivalent plastic strain rate; D = 0: rate-independent.
  double rate_constant = 0.0; ///< D, 1/s
  double rate_exponent = 1.0; ///< q, -
  /// Equivalent plastic strain at which a point fails totally and becomes debris (pressure in
  /// compression only); 0: never fails.
  double failure_plastic_strain = 0.0;
};

/// Which registered model, and the parameters of each model (only the chosen one is used).
struct MaterialParameters
{
  std::string model = "transversely isotropic hyperelastic";
  TissueParameters tissue;
  ElasticPlasticParameters elastic_plastic;
};
} // namespace vulnus::materials
