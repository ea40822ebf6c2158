// Exponential integral Ei(x), x > 0: power series for moderate, asymptotic series for large x.
#include "materials/exponential_integral.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vulnus::materials
{
namespace
{
constexpr double euler_gamma = 0.57721566490153286060651209008240243;
constexpr double asymptotic_threshold = 40.0;

void check_domain(const double x)
{
  if (!(x > 0.0) || !std::isfinite(x))
    throw std::domain_error("exponential_integral_ei: argument " + std::to_string(x) +
                            " is not a finite positive number");
}

/// gamma + ln x + sum_{k>=1} x^k / (k k!), all terms positive; Neumaier summation.
double ei_series(const double x)
{
  double sum = euler_gamma;
  double compensation = 0.0;
  auto add = [&](const double term)
  {
    const double t = sum + term;
    if (std::abs(sum) >= std::abs(term))
      compensation += (sum - t) + term;
    else
      compensation += (term - t) + sum;
    sum = t;
  };
  add(std::log(x));
  double power_over_factorial = 1.0; // x^k / k!
  for (int k = 1; k < 500; ++k)
  {
    power_over_factorial *= x / k;
    const double term = power_over_factorial / k;
    add(term);
    if (term < 1e-18 * std::abs(sum))
      break;
  }
  return sum + compensation;
}

/// e^{-x} Ei(x) ~ (1/x) sum_k k! / x^k, stopped at the smallest term.
double scaled_ei_asymptotic(const double x)
{
  double sum = 1.0;
  double term = 1.0;
  for (int k = 1; k < 200; ++k)
  {
    const double next = term * k / x;
    if (next >= term || next < 1e-18 * sum)
      break;
    term = next;
    sum += term;
  }
  return sum / x;
}
} // namespace

double exponential_integral_ei(const double x)
{
  check_domain(x);
  if (x <= asymptotic_threshold)
    return ei_series(x);
  return std::exp(x) * scaled_ei_asymptotic(x);
}

double scaled_exponential_integral_ei(const double x)
{
  check_domain(x);
  if (x <= asymptotic_threshold)
    return std::exp(-x) * ei_series(x);
  return scaled_ei_asymptotic(x);
}
} // namespace vulnus::materials
