// Elastic-plastic law (the bullet; gelatin with its options): neo-Hookean elasticity with
// multiplicative J2 plasticity, linear isotropic hardening, optional Cowper-Symonds rate
// dependence and failure at a plastic strain; radial return on the deviatoric Kirchhoff stress
// (Simo & Hughes 1998, Computational Inelasticity, box 9.1). Registered as "elastic plastic".
#pragma once

#include "materials/material.h"
#include "materials/material_parameters.h"
#include "materials/volumetric_law.h"

namespace vulnus::materials
{
/// Return map of one update, in Kirchhoff stress (Pa) per unit reference volume.
template <typename Scalar> struct PlasticReturn
{
  Eigen::Matrix<Scalar, 3, 3> kirchhoff_stress;
  Eigen::Matrix<Scalar, 3, 3> elastic_b_bar; ///< b_e~ after the return, det 1
  Scalar equivalent_plastic_strain;          ///< alpha_{n+1}
  Scalar plastic_multiplier;                 ///< Delta gamma (0 if elastic)
  Scalar deviatoric_norm;                    ///< |s_{n+1}|
  Scalar flow_stress;                        ///< current yield stress, rate factor included
  Scalar trial_trace;                        ///< tr b_e~^trial
  Scalar volume_cube_root;                   ///< J^(1/3)
};

/// Simo & Hughes box 9.1 with the volumetric law U(J) of the parameters (Simo-Hughes
/// U = K/2 [(J^2 - 1)/2 - ln J] by default; logarithmic or Hugoniot for water-like gelatin)
/// and W~ = mu/2 (tr b_e~ - 3):
///   b_e~^trial = F~ C_p~^{-1} F~^T (C_p~^{-1} stored in PointState, det 1),
///   s^trial = mu dev b_e~^trial, f^trial = |s^trial| - sqrt(2/3) (sigma_y + H alpha_n),
///   if f^trial > 0: mu_bar = mu tr(b_e~^trial)/3, dgamma solves
///     |s^trial| - 2 mu_bar dgamma = sqrt(2/3) sigma_f(alpha_n + sqrt(2/3) dgamma, rate),
///     sigma_f = (sigma_y + H alpha) (1 + (rate / D)^(1/q)) (Cowper-Symonds; D = 0 or an
///     unknown time step: factor 1), rate = sqrt(2/3) dgamma / dt,
///     s = s^trial - 2 mu_bar dgamma n, alpha += sqrt(2/3) dgamma,
///     b_e~ = s/mu + x I with x solving det b_e~ = 1 (plastic volume preserved, S&H 9.3.2),
///   tau = J U'(J) I + s, sigma = tau / J.
/// Failure (Failure plastic strain > 0): once alpha reaches it the point fails totally
/// (flag total_failure) and is debris from then on: J U'(J) I in compression, nothing in
/// tension, as failed tissue; the stored energy it loses is booked as dissipated.
/// Responses: energy U + W~; dissipated_density the stored energy the return removes,
/// W~(b_e~^trial) - W~(b_e~) = mu/2 (tr b_e~^trial - tr b_e~): the elastic trial stores all
/// the work of the step, so this closes the energy balance of the algorithm exactly (the
/// plastic work sigma_f dalpha agrees only to first order in the elastic strain, which is
/// 8 % for gelatin at yield); von_mises_over_yield = sqrt(3/2) |s| / sigma_f
/// (Kirchhoff, 1 while flowing); p_wave_modulus J U''(J) + 4/3 mu tr(b_e~)/(3 J). Tangent:
/// exact derivative (dual numbers) of the return map from the stored state, i.e. the
/// consistent algorithmic tangent. det F <= 0 throws std::runtime_error. Pa throughout.
class NeoHookeanPlastic final : public MaterialBase<NeoHookeanPlastic>
{
public:
  explicit NeoHookeanPlastic(const ElasticPlasticParameters& parameters);

  std::string model_name() const override { return "elastic plastic"; }
  bool has_plastic_history() const override { return true; }
  double elastic_limit_stress() const override { return prm.yield_stress; }

  using Material::tangent;

  void update_point(const Tensor2& F, const Vector3& a0, std::uint8_t& failure,
                    PlasticHistory& history, PointResponse& response, double time_step) const;

  Tangent tangent(const Tensor2& F, const Vector3& a0, const PointState& state,
                  double time_step) const override;

  /// Return map from the stored state over time_step (state unchanged; 0: rate-free);
  /// Scalar is double or Dual.
  template <typename Scalar>
  PlasticReturn<Scalar> return_map(const Eigen::Matrix<Scalar, 3, 3>& F,
                                   const PlasticHistory& history, double time_step) const;

  /// Cowper-Symonds factor 1 + (rate / D)^(1/q) of the flow stress (1 when D = 0).
  double rate_factor(double plastic_strain_rate) const;

  const ElasticPlasticParameters& parameters() const { return prm; }

private:
  /// Kirchhoff stress of failed debris: J U'(J) I in compression, 0 in tension.
  template <typename Scalar>
  Eigen::Matrix<Scalar, 3, 3> debris_kirchhoff_stress(const Scalar& J) const;

  /// dgamma of the rate-dependent return (Newton safeguarded by bisection in (0, upper]).
  double rate_dependent_multiplier(double norm_trial, double mu_bar, double alpha_n,
                                   double time_step, double upper, double& slope) const;

  ElasticPlasticParameters prm;
  VolumetricLaw volumetric;
};
} // namespace vulnus::materials
