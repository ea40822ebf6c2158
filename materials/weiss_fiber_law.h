// Fiber part of the Weiss 1996 transversely isotropic law: the fiber force lambda dF2/dlambda,
// its stiffness, and its exact strain energy F2 (the toe part needs the exponential integral).
#pragma once

#include <cmath>
#include <vector>

namespace vulnus::materials
{
/// Fiber law of Weiss, Maker and Govindjee (1996), eq. for F2 (docs/DESIGN.md section 3):
///
///   f(lambda) = lambda dF2/dlambda = 0                              lambda < 1
///                                  = c3 (exp(c4 (lambda - 1)) - 1)  1 <= lambda < lambda*
///                                  = c5 lambda + c6                 lambda >= lambda*
///   c6 = c3 (exp(c4 (lambda* - 1)) - 1) - c5 lambda*   (f continuous at lambda*)
///
/// f in Pa. Energy F2(lambda) = int_1^lambda f(s)/s ds, in J/m^3:
///   toe:    c3 [exp(-c4) (Ei(c4 lambda) - Ei(c4)) - ln lambda]
///   linear: F2(lambda*) + c5 (lambda - lambda*) + c6 ln(lambda / lambda*).
/// Valid for c3 >= 0, c4 > 0, c5 >= 0, lambda* >= 1.
///
/// The toe energy is evaluated from a table built at construction: nodes x_j in x = c4 lambda
/// at spacing min(1, c4/2), the exact Ei at each node and the Taylor series of
/// Ei(x_j + h) - Ei(x_j) = e^{x_j} sum_k b_k h^k (b_k from e^s / (x_j + s)), truncated below
/// 1e-17 relative; so energy() agrees with the direct Ei formula (energy_from_ei()) to
/// round-off at the cost of one short Horner polynomial instead of a long series.
class WeissFiberLaw
{
public:
  WeissFiberLaw(double c3, double c4, double c5, double lambda_star);

  /// lambda dF2/dlambda (Pa); T is double or Dual.
  template <typename T> T force(const T& lambda) const
  {
    using std::exp;
    if (lambda < T(1.0))
      return T(0.0);
    if (lambda < T(lambda_star))
      return c3 * (exp(c4 * (lambda - 1.0)) - 1.0);
    return c5 * lambda + c6;
  }

  /// lambda df/dlambda (Pa): the fiber modulus with respect to logarithmic stretch.
  double stiffness(double lambda) const;

  /// F2(lambda) (J/m^3), exact integral of f(s)/s from 1; zero for lambda <= 1.
  double energy(double lambda) const;

  /// F2(lambda) evaluated directly from Ei (slow reference for tests).
  double energy_from_ei(double lambda) const;

  double continuity_constant_c6() const { return c6; }
  double toe_energy_at_lambda_star() const { return energy_star; }

private:
  double toe_energy(double lambda) const;

  double c3;
  double c4;
  double c5;
  double lambda_star;
  double c6;
  double energy_star = 0.0;

  // Toe-energy table.
  double node_spacing = 1.0; ///< in x = c4 lambda
  int n_terms = 0;
  std::vector<double> node_lambda;
  std::vector<double> node_base;         ///< exp(-c4) (Ei(x_j) - Ei(c4))
  std::vector<double> node_scale;        ///< exp(x_j - c4)
  std::vector<double> node_coefficients; ///< b_1..b_{n_terms} per node
};
} // namespace vulnus::materials
