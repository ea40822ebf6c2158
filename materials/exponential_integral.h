// The exponential integral Ei(x) for x > 0, needed for the exact strain energy of the
// exponential toe region of the Weiss fiber law (docs/DESIGN.md section 3).
#pragma once

namespace vulnus::materials
{
/// Ei(x) = PV int_{-inf}^{x} e^t / t dt for x > 0 (throws std::domain_error otherwise).
/// Convergent series gamma + ln x + sum x^k / (k k!) (compensated summation) for x <= 40,
/// asymptotic series e^x / x sum k! / x^k beyond (truncated before its smallest term, which
/// is below 1e-16 relative there). Relative error about 1e-15, except near the zero of Ei
/// at x = 0.3725 where only the absolute error (about 1e-16) is small.
double exponential_integral_ei(double x);

/// e^{-x} Ei(x) for x > 0, without overflow for large x.
double scaled_exponential_integral_ei(double x);
} // namespace vulnus::materials
