// Elastic-plastic neo-Hookean bullet: radial return (Simo & Hughes box 9.1), tangent by
// dual numbers through the return map, registration as "elastic plastic".
#include "materials/neo_hookean_plastic.h"

#include "materials/dual_number.h"
#include "materials/material_registry.h"

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

NeoHookeanPlastic::NeoHookeanPlastic(const ElasticPlasticParameters& parameters) : prm(parameters)
{
}

template <typename Scalar>
PlasticReturn<Scalar> NeoHookeanPlastic::return_map(const Matrix3<Scalar>& F,
                                                    const PlasticHistory& history) const
{
  using std::cbrt;
  using std::sqrt;
  const double mu = prm.shear_modulus;
  const double H = prm.hardening_modulus;
  const Matrix3<Scalar> identity = Matrix3<Scalar>::Identity();

  const Scalar J = F.determinant();
  if (!(value_of(J) > 0.0))
    throw_inverted(value_of(J));
  const Matrix3<Scalar> F_bar = (1.0 / cbrt(J)) * F;
  const Matrix3<Scalar> C_p_inverse =
      from_voigt(history.inverse_plastic_cauchy_green).template cast<Scalar>();
  const Matrix3<Scalar> b_trial = F_bar * C_p_inverse * F_bar.transpose();
  const Scalar I_e = b_trial.trace() / 3.0;
  const Matrix3<Scalar> s_trial = mu * (b_trial - I_e * identity);
  const Scalar norm_trial = sqrt((s_trial.cwiseProduct(s_trial)).sum());
  const double alpha_n = history.equivalent_plastic_strain;
  const Scalar f_trial = norm_trial - sqrt_two_thirds * (prm.yield_stress + H * alpha_n);

  PlasticReturn<Scalar> result;
  const Scalar pressure_times_J = 0.5 * prm.bulk_modulus * (J * J - 1.0);
  if (!(f_trial > Scalar(0.0)))
  {
    result.kirchhoff_stress = pressure_times_J * identity + s_trial;
    result.elastic_b_bar = b_trial;
    result.equivalent_plastic_strain = Scalar(alpha_n);
    result.plastic_multiplier = Scalar(0.0);
    result.deviatoric_norm = norm_trial;
    return result;
  }

  const Scalar mu_bar = mu * I_e;
  const Scalar delta_gamma = f_trial / (2.0 * mu_bar + 2.0 / 3.0 * H);
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
  return result;
}

template PlasticReturn<double> NeoHookeanPlastic::return_map(const Matrix3<double>&,
                                                             const PlasticHistory&) const;
template PlasticReturn<Dual> NeoHookeanPlastic::return_map(const Matrix3<Dual>&,
                                                           const PlasticHistory&) const;

void NeoHookeanPlastic::update_point(const Tensor2& F, const Vector3&, std::uint8_t&,
                                     PlasticHistory& history, PointResponse& response) const
{
  const double J = F.determinant();
  if (!(J > 0.0) || !std::isfinite(J))
    throw_inverted(J);
  const PlasticReturn<double> r = return_map(F, history);
  const double flow_stress = prm.yield_stress + prm.hardening_modulus * r.equivalent_plastic_strain;

  if (r.plastic_multiplier > 0.0)
  {
    const Tensor2 F_bar_inverse = std::cbrt(J) * F.inverse();
    history.inverse_plastic_cauchy_green =
        to_voigt(F_bar_inverse * r.elastic_b_bar * F_bar_inverse.transpose());
  }
  history.equivalent_plastic_strain = r.equivalent_plastic_strain;

  const double trace_b = r.elastic_b_bar.trace();
  const double K = prm.bulk_modulus;
  response.cauchy_stress = r.kirchhoff_stress / J;
  response.energy_density =
      0.5 * K * (0.5 * (J * J - 1.0) - std::log(J)) + 0.5 * prm.shear_modulus * (trace_b - 3.0);
  response.dissipated_density = r.deviatoric_norm * r.plastic_multiplier;
  response.von_mises_over_yield = std::sqrt(1.5) * r.deviatoric_norm / flow_stress;
  response.p_wave_modulus =
      0.5 * K * (J + 1.0 / J) + 4.0 / 3.0 * prm.shear_modulus * trace_b / (3.0 * J);
}

Tangent NeoHookeanPlastic::tangent(const Tensor2& F, const Vector3&, const PointState& state) const
{
  Tangent D;
  const Matrix3<Dual> F_dual = F.cast<Dual>();
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
      Matrix3<Dual> F_seeded = F_dual;
      F_seeded(k, L).d = 1.0;
      const PlasticReturn<Dual> r = return_map(F_seeded, state.plastic);
      // P = tau F^{-T}
      const Matrix3<Dual> P = r.kirchhoff_stress * F_seeded.inverse().transpose();
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
}

const bool elastic_plastic_registered = register_material_model(
    "elastic plastic",
    "Neo-Hookean elasticity (U = K/2 [(J^2-1)/2 - ln J], W = mu/2 (tr b_e~ - 3)) with "
    "multiplicative J2 plasticity and linear isotropic hardening, radial return on the "
    "deviatoric Kirchhoff stress (Simo & Hughes box 9.1), plastic volume preserved. Entries: "
    "Bulk modulus, Shear modulus, Yield stress, Hardening modulus (Pa). Reports von Mises / "
    "yield so a scene can tell whether a rigid impactor would do.",
    [](const MaterialParameters& parameters) -> std::unique_ptr<Material>
    { return std::make_unique<NeoHookeanPlastic>(parameters.elastic_plastic); },
    check_elastic_plastic);
} // namespace
} // namespace vulnus::materials
