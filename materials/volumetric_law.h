// A law's volumetric energy U(J): the paper's logarithmic law, a law whose compression follows
// the linear shock Hugoniot of water-like tissue and gelatin (docs/volumetric_law.md), or the
// elastic-plastic bullet's Simo-Hughes law.
#pragma once

#include "materials/dual_number.h"
#include "materials/material_parameters.h"

#include <cmath>

namespace vulnus::materials
{
/// U(J) of a law, with sigma_vol = U'(J) I (Cauchy) and the pressure p = -U'(J).
///
/// logarithmic: U = K/2 (ln J)^2, p = -K ln J / J.
///
/// Simo-Hughes: U = K/2 [(J^2 - 1)/2 - ln J], J U' = K/2 (J^2 - 1), J U'' = K/2 (J + 1/J).
///
/// Hugoniot (J < 1): the pressure of the linear shock Hugoniot Us = c0 + s up with
/// K = rho0 c0^2, written in eta = 1 - J (= up / Us on the Hugoniot):
///   p = K eta / w^2,   w = 1 - s eta,
///   U = K/s^2 (1/w + ln w - 1)          (U'(J) = -p; U, U' and U'' = K agree with the
///                                         logarithmic law at J = 1)
///   J U''(J) = J K (1 + s eta) / w^3.
/// Tension (J >= 1) keeps the logarithmic law. The thermal (Grueneisen) term is left out: at
/// the pressures of a bullet in tissue (below 1 GPa) the shock's entropy is a small part of
/// the energy. The Hugoniot pressure grows without bound as w -> 0 (J -> 1 - 1/s); below
/// w = hugoniot_w_floor the law continues with the constant U'' of that point (p linear in
/// J), so no compression makes it singular.
class VolumetricLaw
{
public:
  static constexpr double hugoniot_w_floor = 0.25;

  VolumetricLaw(const double bulk_modulus, const VolumetricLawKind law_kind,
                const double hugoniot_slope)
      : K(bulk_modulus), s(hugoniot_slope), kind(law_kind),
        J_floor(1.0 - (1.0 - hugoniot_w_floor) / hugoniot_slope)
  {
  }

  explicit VolumetricLaw(const TissueParameters& p)
      : VolumetricLaw(p.bulk_modulus, p.volumetric_law, p.hugoniot_slope)
  {
  }

  /// J U'(J): the Kirchhoff volumetric stress is this times I.
  template <typename Scalar> Scalar kirchhoff_pressure_term(const Scalar& J) const
  {
    using std::log;
    if (kind == VolumetricLawKind::simo_hughes)
      return 0.5 * K * (J * J - 1.0);
    if (kind == VolumetricLawKind::logarithmic || !(value_of(J) < 1.0))
      return K * log(J);
    return J * derivative(J);
  }

  /// U(J) per unit reference volume.
  double energy(const double J) const
  {
    if (kind == VolumetricLawKind::simo_hughes)
      return 0.5 * K * (0.5 * (J * J - 1.0) - std::log(J));
    if (kind == VolumetricLawKind::logarithmic || !(J < 1.0))
      return 0.5 * K * std::log(J) * std::log(J);
    if (J < J_floor)
    {
      const double d = J - J_floor;
      return hugoniot_energy(J_floor) + derivative(J_floor) * d +
             0.5 * second_derivative(J_floor) * d * d;
    }
    return hugoniot_energy(J);
  }

  /// K_t = J U''(J), the tangent bulk modulus (may be negative in tension, J > e).
  double tangent_bulk_modulus(const double J) const
  {
    if (kind == VolumetricLawKind::simo_hughes)
      return 0.5 * K * (J + 1.0 / J);
    if (kind == VolumetricLawKind::logarithmic || !(J < 1.0))
      return K * (1.0 - std::log(J)) / J;
    return J * second_derivative(J < J_floor ? J_floor : J);
  }

private:
  /// U'(J) on the compressive Hugoniot branch, continued linearly below J_floor.
  template <typename Scalar> Scalar derivative(const Scalar& J) const
  {
    if (value_of(J) < J_floor)
      return derivative(J_floor) + second_derivative(J_floor) * (J - J_floor);
    const Scalar eta = 1.0 - J;
    const Scalar w = 1.0 - s * eta;
    return -K * eta / (w * w);
  }

  double second_derivative(const double J) const
  {
    const double eta = 1.0 - J;
    const double w = 1.0 - s * eta;
    return K * (1.0 + s * eta) / (w * w * w);
  }

  /// K/s^2 (1/w + ln w - 1) written as K/s^2 (x/w + ln(1 - x)), x = s eta, which keeps
  /// its accuracy as J -> 1 (the first form cancels to round-off there).
  double hugoniot_energy(const double J) const
  {
    const double x = s * (1.0 - J);
    return K / (s * s) * (x / (1.0 - x) + std::log1p(-x));
  }

  double K;
  double s;
  VolumetricLawKind kind;
  double J_floor; ///< J where w = hugoniot_w_floor
};
} // namespace vulnus::materials
