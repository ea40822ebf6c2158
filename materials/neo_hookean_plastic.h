// Elastic-plastic bullet: neo-Hookean elasticity with multiplicative J2 plasticity and linear
// isotropic hardening, radial return on the deviatoric Kirchhoff stress (Simo & Hughes 1998,
// Computational Inelasticity, box 9.1). Registered as "elastic plastic".
#pragma once

#include "materials/material.h"
#include "materials/material_parameters.h"

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
};

/// Simo & Hughes box 9.1 with U(J) = K/2 [(J^2 - 1)/2 - ln J], W~ = mu/2 (tr b_e~ - 3):
///   b_e~^trial = F~ C_p~^{-1} F~^T (C_p~^{-1} stored in PointState, det 1),
///   s^trial = mu dev b_e~^trial, f^trial = |s^trial| - sqrt(2/3) (sigma_y + H alpha_n),
///   if f^trial > 0: mu_bar = mu tr(b_e~^trial)/3, dgamma = f^trial / (2 mu_bar + 2H/3),
///     s = s^trial - 2 mu_bar dgamma n, alpha += sqrt(2/3) dgamma,
///     b_e~ = s/mu + x I with x solving det b_e~ = 1 (plastic volume preserved, S&H 9.3.2),
///   tau = J U'(J) I + s, sigma = tau / J.
/// Responses: energy U + W~; dissipated_density the backward-Euler plastic work
/// |s_{n+1}| dgamma = (sigma_y + H alpha_{n+1}) dalpha; von_mises_over_yield
/// = sqrt(3/2) |s| / (sigma_y + H alpha) (Kirchhoff, 1 while flowing); p_wave_modulus
/// K/2 (J + 1/J) + 4/3 mu tr(b_e~)/(3 J). Tangent: exact derivative (dual numbers) of the
/// return map from the stored state, i.e. the consistent algorithmic tangent.
/// det F <= 0 throws std::runtime_error. Pa throughout.
class NeoHookeanPlastic final : public MaterialBase<NeoHookeanPlastic>
{
public:
  explicit NeoHookeanPlastic(const ElasticPlasticParameters& parameters);

  std::string model_name() const override { return "elastic plastic"; }
  bool has_plastic_history() const override { return true; }

  void update_point(const Tensor2& F, const Vector3& a0, std::uint8_t& failure,
                    PlasticHistory& history, PointResponse& response) const;

  Tangent tangent(const Tensor2& F, const Vector3& a0, const PointState& state) const override;

  /// Return map from the stored state (state unchanged); Scalar is double or Dual.
  template <typename Scalar>
  PlasticReturn<Scalar> return_map(const Eigen::Matrix<Scalar, 3, 3>& F,
                                   const PlasticHistory& history) const;

  const ElasticPlasticParameters& parameters() const { return prm; }

private:
  ElasticPlasticParameters prm;
};
} // namespace vulnus::materials
