// The artificial bulk (shock) viscosity of the explicit discretisations, shared by the MPM
// points and the explicit far field's cells so that a wave crossing the hybrid interface meets
// the same damping on both sides: q = rho (q1 c h |d| + q2 h^2 d^2) in compression (d = d ln J
// / dt < 0), zero in expansion (von Neumann and Richtmyer 1950; the linear term after Landshoff
// 1955; the coefficient pair 0.06 / 1.5 of the hydrocodes, e.g. LS-DYNA's solid elements).
#pragma once

namespace vulnus::materials
{
struct ShockViscosity
{
  double linear = 0.0;    ///< q1 [-]
  double quadratic = 0.0; ///< q2 [-]

  bool active() const { return linear > 0.0 || quadratic > 0.0; }

  /// The viscous pressure q (Pa) at current density rho, wave speed c and length h, for the
  /// volumetric rate d = d ln J / dt (1/s).
  double pressure(const double density, const double wave_speed, const double h,
                  const double rate) const
  {
    if (!(rate < 0.0))
      return 0.0;
    return density * (linear * wave_speed * h * -rate + quadratic * h * h * rate * rate);
  }
};
} // namespace vulnus::materials
