// Weiss 1996 fiber law: force, stiffness and exact energy (table of the toe energy).
#include "materials/weiss_fiber_law.h"

#include "materials/exponential_integral.h"

#include <algorithm>
#include <cmath>

namespace vulnus::materials
{
WeissFiberLaw::WeissFiberLaw(const double c3, const double c4, const double c5,
                             const double lambda_star)
    : c3(c3), c4(c4), c5(c5), lambda_star(lambda_star),
      c6(c3 * (std::exp(c4 * (lambda_star - 1.0)) - 1.0) - c5 * lambda_star)
{
  if (!(c4 > 0.0) || !(lambda_star >= 1.0) || c3 == 0.0)
    return; // no toe region to tabulate (parameter checks reject c4 <= 0, lambda* < 1)

  node_spacing = std::min(1.0, 0.5 * c4);
  const int n_intervals =
      std::max(1, static_cast<int>(std::ceil(c4 * (lambda_star - 1.0) / node_spacing)));
  const double h_max = 0.5 * node_spacing;
  const double scaled_ei_c4 = scaled_exponential_integral_ei(c4);

  // Coefficients a_i of e^s / (x0 + s) = sum a_i s^i: x0 a_0 = 1, x0 a_i + a_{i-1} = 1/i!.
  // Then int_0^h e^s / (x0 + s) ds = sum_{k>=1} b_k h^k with b_k = a_{k-1} / k.
  constexpr int max_terms = 60;
  std::vector<std::vector<double>> b(n_intervals + 1);
  for (int j = 0; j <= n_intervals; ++j)
  {
    const double x0 = c4 + j * node_spacing;
    double a = 1.0 / x0;
    double inverse_factorial = 1.0;
    for (int k = 1; k <= max_terms; ++k)
    {
      b[j].push_back(a / k);
      inverse_factorial /= k;
      a = (inverse_factorial - a) / x0;
    }
    int needed = 1; // the last term that still matters at |h| <= h_max
    for (int k = 2; k <= max_terms; ++k)
      if (std::abs(b[j][k - 1]) * std::pow(h_max, k - 1) >= 1e-18 * b[j][0])
        needed = k;
    n_terms = std::max(n_terms, needed);
  }

  node_coefficients.assign(static_cast<std::size_t>(n_intervals + 1) * n_terms, 0.0);
  for (int j = 0; j <= n_intervals; ++j)
  {
    const double x0 = c4 + j * node_spacing;
    node_lambda.push_back(x0 / c4);
    node_scale.push_back(std::exp(x0 - c4));
    node_base.push_back(
        j == 0 ? 0.0 : node_scale.back() * scaled_exponential_integral_ei(x0) - scaled_ei_c4);
    for (int k = 0; k < n_terms; ++k)
      node_coefficients[static_cast<std::size_t>(j) * n_terms + k] = b[j][k];
  }
  energy_star = toe_energy(lambda_star);
}

double WeissFiberLaw::stiffness(const double lambda) const
{
  if (lambda < 1.0)
    return 0.0;
  if (lambda < lambda_star)
    return c3 * c4 * lambda * std::exp(c4 * (lambda - 1.0));
  return c5 * lambda;
}

double WeissFiberLaw::toe_energy(const double lambda) const
{
  if (c3 == 0.0 || node_lambda.empty())
    return 0.0;
  const int last = static_cast<int>(node_lambda.size()) - 1;
  const int j =
      std::clamp(static_cast<int>(std::lround((lambda - 1.0) * c4 / node_spacing)), 0, last);
  const double h = c4 * (lambda - node_lambda[j]);
  const double* coefficient = &node_coefficients[static_cast<std::size_t>(j) * n_terms];
  double polynomial = 0.0;
  for (int k = n_terms - 1; k >= 0; --k)
    polynomial = polynomial * h + coefficient[k];
  polynomial *= h;
  return c3 * (node_base[j] + node_scale[j] * polynomial - std::log(lambda));
}

double WeissFiberLaw::energy(const double lambda) const
{
  if (lambda <= 1.0)
    return 0.0;
  if (lambda < lambda_star)
    return toe_energy(lambda);
  return energy_star + c5 * (lambda - lambda_star) + c6 * std::log(lambda / lambda_star);
}

double WeissFiberLaw::energy_from_ei(const double lambda) const
{
  if (lambda <= 1.0)
    return 0.0;
  auto toe = [&](const double l)
  {
    if (c3 == 0.0)
      return 0.0;
    return c3 * (std::exp(c4 * (l - 1.0)) * scaled_exponential_integral_ei(c4 * l) -
                 scaled_exponential_integral_ei(c4) - std::log(l));
  };
  if (lambda < lambda_star)
    return toe(lambda);
  return toe(lambda_star) + c5 * (lambda - lambda_star) + c6 * std::log(lambda / lambda_star);
}
} // namespace vulnus::materials
