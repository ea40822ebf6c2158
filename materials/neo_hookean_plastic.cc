// Elastic-plastic neo-Hookean law: radial return (Simo & Hughes box 9.1) with Cowper-Symonds
// rate dependence and failure, tangent by dual numbers through the return map, registration
// as "elastic plastic".
#include "materials/neo_hookean_plastic.h"

#include "materials/dual_number.h"
#include "materials/material_registry.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::materials
{
namespace
{
template <typename Scalar> using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

const double sqrt_two_thirds = std::sqrt(2.0 / 3.0);

Tensor2 from_voigt(const std::array<double, 6>& v)
{
  Tensor2 m;
  m << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
  return m;
}

std::array<double, 6> to_voigt(const Tensor2& m)
{
  return {{m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(0, 1) + m(1, 0)), 0.5 * (m(1, 2) + m(2, 1)),
           0.5 * (m(0, 2) + m(2, 0))}};
}

void throw_inverted(const double J)
{
  std::ostringstream message;
  message << "elastic plastic material: det F = " << J
          << " <= 0 (inverted element/particle); reduce the time step";
  throw std::runtime_error(message.str());
}
} // namespace

NeoHookeanPlastic::NeoHookeanPlastic(const ElasticPlasticParameters& parameters)
    : prm(parameters),
      volumetric(parameters.bulk_modulus, parameters.volumetric_law, parameters.hugoniot_slope)
{
}

double NeoHookeanPlastic::rate_factor(const double plastic_strain_rate) const
{
  if (!(prm.rate_constant > 0.0) || !(plastic_strain_rate > 0.0))
    return 1.0;
  return 1.0 + std::pow(plastic_strain_rate / prm.rate_constant, 1.0 / prm.rate_exponent);
}

double NeoHookeanPlastic::rate_dependent_multiplier(const double norm_trial, const double mu_bar,
                                                   const double alpha_n, const double time_step,
                                                   const double upper, double& slope) const
{
  const double H = prm.hardening_modulus;
  const double c = sqrt_two_thirds;
  const double D = prm.rate_constant, q = prm.rate_exponent;
  // g(dgamma) = |s^trial| - 2 mu_bar dgamma - c sigma_f: decreasing, g(0) > 0 >= g(upper).
  auto g = [&](const double x, double& dg)
  {
    const double hardened = prm.yield_stress + H * (alpha_n + c * x);
    const double ratio = c * x / (time_step * D);
    const double power = ratio > 0.0 ? std::pow(ratio, 1.0 / q) : 0.0;
    const double dpower = ratio > 0.0 ? power / (q * x) : 0.0;
    dg = -2.0 * mu_bar - c * (H * c * (1.0 + power) + hardened * dpower);
    return norm_trial - 2.0 * mu_bar * x - c * hardened * (1.0 + power);
  };
  double lo = 0.0, hi = upper, x = upper, dg = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    const double value = g(x, dg);
    if (value > 0.0)
      lo = x;
    else
      hi = x;
    double next = x - value / dg;
    if (!(next > lo && next < hi))
      next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-14 * upper || hi - lo <= 1e-15 * upper)
    {
      x = next;
      break;
    }
    x = next;
  }
  g(x, slope);
  return x;
}

template <typename Scalar>
Matrix3<Scalar> NeoHookeanPlastic::debris_kirchhoff_stress(const Scalar& J) const
{
  if (!(value_of(J) < 1.0))
    return Matrix3<Scalar>::Zero();
  return volumetric.kirchhoff_pressure_term(J) * Matrix3<Scalar>::Identity();
}

template <typename Scalar>
PlasticReturn<Scalar> NeoHookeanPlastic::return_map(const Matrix3<Scalar>& F,
                                                    const PlasticHistory& history,
                                                    const double time_step) const
{
  using std::cbrt;
  using std::sqrt;
  const double mu = prm.shear_modulus;
  const double H = prm.hardening_modulus;
  const Matrix3<Scalar> identity = Matrix3<Scalar>::Identity();

  const Scalar J = F.determinant();
  if (!(value_of(J) > 0.0))
    throw_inverted(value_of(J));
  const Scalar volume_cube_root = cbrt(J);
  const Matrix3<Scalar> F_bar = (1.0 / volume_cube_root) * F;
  const Matrix3<Scalar> C_p_inverse =
      from_voigt(history.inverse_plastic_cauchy_green).template cast<Scalar>();
  const Matrix3<Scalar> b_trial = F_bar * C_p_inverse * F_bar.transpose();
  const Scalar I_e = b_trial.trace() / 3.0;
  const Matrix3<Scalar> s_trial = mu * (b_trial - I_e * identity);
  const Scalar norm_trial = sqrt((s_trial.cwiseProduct(s_trial)).sum());
  const double alpha_n = history.equivalent_plastic_strain;
  const Scalar f_trial = norm_trial - sqrt_two_thirds * (prm.yield_stress + H * alpha_n);

  PlasticReturn<Scalar> result;
  const Scalar pressure_times_J = volumetric.kirchhoff_pressure_term(J);
  if (!(f_trial > Scalar(0.0)))
  {
    result.kirchhoff_stress = pressure_times_J * identity + s_trial;
    result.elastic_b_bar = b_trial;
    result.equivalent_plastic_strain = Scalar(alpha_n);
    result.plastic_multiplier = Scalar(0.0);
    result.deviatoric_norm = norm_trial;
    result.flow_stress = Scalar(prm.yield_stress + H * alpha_n);
    result.trial_trace = 3.0 * I_e;
    result.volume_cube_root = volume_cube_root;
    return result;
  }

  const Scalar mu_bar = mu * I_e;
  Scalar delta_gamma = f_trial / (2.0 * mu_bar + 2.0 / 3.0 * H);
  Scalar flow_stress = prm.yield_stress + H * (alpha_n + sqrt_two_thirds * delta_gamma);
  if (prm.rate_constant > 0.0 && time_step > 0.0)
  {
    // Solved in double; one Newton step in Scalar then carries the exact derivative
    // d dgamma = -dg / g' of a dual number (implicit function theorem).
    double slope = 0.0;
    const double x = rate_dependent_multiplier(value_of(norm_trial), value_of(mu_bar), alpha_n,
                                               time_step, value_of(delta_gamma), slope);
    const double factor = rate_factor(sqrt_two_thirds * x / time_step);
    const double hardened = prm.yield_stress + H * (alpha_n + sqrt_two_thirds * x);
    const Scalar g = norm_trial - 2.0 * mu_bar * x - sqrt_two_thirds * hardened * factor;
    delta_gamma = Scalar(x) - g / slope;
    flow_stress = (norm_trial - 2.0 * mu_bar * delta_gamma) / sqrt_two_thirds;
  }
  const Matrix3<Scalar> s = (1.0 - 2.0 * mu_bar * delta_gamma / norm_trial) * s_trial;

  // b_e~ = A + x I with A = s / mu deviatoric: det = x^3 - (tr A^2 / 2) x + det A = 1.
  const Matrix3<Scalar> A = s / mu;
  const Scalar half_trace_A2 = 0.5 * (A.cwiseProduct(A)).sum();
  const Scalar det_A = A.determinant();
  Scalar x = I_e;
  for (int iteration = 0; iteration < 30; ++iteration)
  {
    const Scalar g = x * x * x - half_trace_A2 * x + det_A - 1.0;
    const Scalar step = g / (3.0 * x * x - half_trace_A2);
    x -= step;
    if (std::abs(value_of(step)) < 1e-15 * std::abs(value_of(x)))
    {
      // One more step converges the derivative part of a dual number as well.
      x -= (x * x * x - half_trace_A2 * x + det_A - 1.0) / (3.0 * x * x - half_trace_A2);
      break;
    }
  }

  result.kirchhoff_stress = pressure_times_J * identity + s;
  result.elastic_b_bar = A + x * identity;
  result.plastic_multiplier = delta_gamma;
  result.equivalent_plastic_strain = alpha_n + sqrt_two_thirds * delta_gamma;
  result.deviatoric_norm = norm_trial - 2.0 * mu_bar * delta_gamma;
  result.flow_stress = flow_stress;
  result.trial_trace = 3.0 * I_e;
  result.volume_cube_root = volume_cube_root;
  return result;
}

template PlasticReturn<double> NeoHookeanPlastic::return_map(const Matrix3<double>&,
                                                             const PlasticHistory&,
                                                             double) const;
template PlasticReturn<Dual> NeoHookeanPlastic::return_map(const Matrix3<Dual>&,
                                                           const PlasticHistory&, double) const;

void NeoHookeanPlastic::update_point(const Tensor2& F, const Vector3&, std::uint8_t& failure,
                                     PlasticHistory& history, PointResponse& response,
                                     const double time_step) const
{
  const double J = F.determinant();
  if (!(J > 0.0) || !std::isfinite(J))
    throw_inverted(J);
  // Debris: the volumetric stress, energy and wave in compression, nothing in tension.
  auto set_debris_response = [&]()
  {
    response.cauchy_stress = debris_kirchhoff_stress(J) / J;
    response.energy_density = J < 1.0 ? volumetric.energy(J) : 0.0;
    response.von_mises_over_yield = 0.0;
    response.p_wave_modulus = J < 1.0 ? std::max(volumetric.tangent_bulk_modulus(J), 0.0) : 0.0;
  };
  if (failure & total_failure)
  {
    set_debris_response();
    response.dissipated_density = 0.0;
    return;
  }
  const PlasticReturn<double> r = return_map(F, history, time_step);

  if (r.plastic_multiplier > 0.0)
  {
    const Tensor2 F_bar_inverse = r.volume_cube_root * F.inverse();
    history.inverse_plastic_cauchy_green =
        to_voigt(F_bar_inverse * r.elastic_b_bar * F_bar_inverse.transpose());
  }
  history.equivalent_plastic_strain = r.equivalent_plastic_strain;

  const double trace_b = r.elastic_b_bar.trace();
  response.cauchy_stress = r.kirchhoff_stress / J;
  response.energy_density = volumetric.energy(J) + 0.5 * prm.shear_modulus * (trace_b - 3.0);
  response.dissipated_density =
      r.plastic_multiplier > 0.0 ? 0.5 * prm.shear_modulus * (r.trial_trace - trace_b) : 0.0;
  response.von_mises_over_yield = std::sqrt(1.5) * r.deviatoric_norm / r.flow_stress;
  response.p_wave_modulus = std::max(volumetric.tangent_bulk_modulus(J), 0.0) +
                            4.0 / 3.0 * prm.shear_modulus * trace_b / (3.0 * J);

  if (prm.failure_plastic_strain > 0.0 &&
      !(r.equivalent_plastic_strain < prm.failure_plastic_strain))
  {
    failure = total_failure;
    const double intact_energy = response.energy_density;
    set_debris_response();
    response.dissipated_density += intact_energy - response.energy_density;
  }
}

Tangent NeoHookeanPlastic::tangent(const Tensor2& F, const Vector3&, const PointState& state,
                                   const double time_step) const
{
  Tangent D;
  const Matrix3<Dual> F_dual = F.cast<Dual>();
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
      Matrix3<Dual> F_seeded = F_dual;
      F_seeded(k, L).d = 1.0;
      const Matrix3<Dual> tau =
          (state.failure & total_failure)
            ? debris_kirchhoff_stress(F_seeded.determinant())
            : Matrix3<Dual>(return_map(F_seeded, state.plastic, time_step).kirchhoff_stress);
      // P = tau F^{-T}
      const Matrix3<Dual> P = tau * F_seeded.inverse().transpose();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          D(3 * i + j, 3 * k + L) = P(i, j).d;
    }
  return D;
}

namespace
{
void check_elastic_plastic(const MaterialParameters& parameters, std::vector<ParameterProblem>& problems)
{
  const ElasticPlasticParameters& p = parameters.elastic_plastic;
  auto require = [&](const bool ok, const std::string& entry, const double value,
                     const std::string& problem, const std::string& remedy)
  {
    if (!ok)
    {
      std::ostringstream got;
      got << problem << " (got " << value << ")";
      problems.push_back({{entry}, got.str(), remedy});
    }
  };
  auto finite = [](const double x) { return std::isfinite(x); };
  require(finite(p.bulk_modulus) && p.bulk_modulus > 0.0, "Bulk modulus", p.bulk_modulus,
          "must be positive", "give K in Pa, e.g. 117e9");
  require(finite(p.shear_modulus) && p.shear_modulus > 0.0, "Shear modulus", p.shear_modulus,
          "must be positive", "give mu in Pa, e.g. 53.8e9");
  require(finite(p.yield_stress) && p.yield_stress > 0.0, "Yield stress", p.yield_stress,
          "must be positive", "give the initial yield stress in Pa, e.g. 422.6e6");
  require(finite(p.hardening_modulus) && p.hardening_modulus >= 0.0, "Hardening modulus",
          p.hardening_modulus, "must be zero or positive",
          "give the linear isotropic hardening modulus in Pa, e.g. 53.8e6");
  require(finite(p.rate_constant) && p.rate_constant >= 0.0, "Rate constant", p.rate_constant,
          "must be zero (rate-independent) or positive",
          "give the Cowper-Symonds D in 1/s, or 0 for a rate-independent yield stress");
  require(finite(p.rate_exponent) && p.rate_exponent >= 0.1 && p.rate_exponent <= 100.0,
          "Rate exponent", p.rate_exponent, "must lie in [0.1, 100]",
          "give the Cowper-Symonds exponent q, e.g. 5 (steel) or 1 (a linear viscosity)");
  require(finite(p.failure_plastic_strain) && p.failure_plastic_strain >= 0.0,
          "Failure plastic strain", p.failure_plastic_strain,
          "must be zero (never fails) or positive",
          "give the equivalent plastic strain at total failure, e.g. 0.9, or 0");
  if (p.volumetric_law == VolumetricLawKind::hugoniot)
    require(finite(p.hugoniot_slope) && p.hugoniot_slope >= 0.5 && p.hugoniot_slope <= 4.0,
            "Hugoniot slope", p.hugoniot_slope, "must lie in [0.5, 4]",
            "give s of Us = c0 + s up, about 1.8-2 for water and gelatin");
}

const bool elastic_plastic_registered = register_material_model(
    "elastic plastic",
    "Neo-Hookean elasticity (W = mu/2 (tr b_e~ - 3); U(J) Simo-Hughes K/2 [(J^2-1)/2 - ln J], "
    "logarithmic or Hugoniot) with multiplicative J2 plasticity, linear isotropic hardening "
    "and optional Cowper-Symonds rate dependence (sigma_y + H alpha)(1 + (alpha_dot/D)^(1/q)), "
    "radial return on the deviatoric Kirchhoff stress (Simo & Hughes box 9.1), plastic volume "
    "preserved; optional total failure at an equivalent plastic strain (debris: pressure in "
    "compression only). Entries: Bulk modulus, Shear modulus, Yield stress, Hardening modulus "
    "(Pa), Volumetric law, Hugoniot slope, Rate constant (1/s), Rate exponent, Failure plastic "
    "strain. Reports von Mises / yield so a scene can tell whether a rigid impactor would do.",
    [](const MaterialParameters& parameters) -> std::unique_ptr<Material>
    { return std::make_unique<NeoHookeanPlastic>(parameters.elastic_plastic); },
    check_elastic_plastic);
} // namespace
} // namespace vulnus::materials
