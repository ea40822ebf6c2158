// The divergence-free shear mode of a nearly incompressible square, the analytic problem of the
// locking verification (tests and benchmarks/locking): u = A (sin kx cos ky, -cos kx sin ky, 0)
// in a square of side L = pi / k between rollers (plane strain) rings at
// T = 2 pi / (k sqrt(2 mu / rho)) whatever the bulk modulus. Started as a velocity field of
// strain amplitude 1e-4; the period is measured from the first two zero crossings of the
// modal velocity (at T/4 and 3T/4).
#pragma once

#include "fem/fem_parameters.h"

namespace vulnus::verification
{
struct ShearModeResult
{
  double period_ratio = 0.0; ///< measured over analytic period (0: fewer than two crossings)
  unsigned long steps = 0;
  double seconds = 0.0; ///< wall time of the run
};

/// MPM, linear shape functions, 2 x 2 x 2 points per cell, MUSL, CFL 0.4, a square of
/// `cells` cells per side and two cells thick; with or without the cell-averaged volume change.
ShearModeResult mpm_shear_mode(unsigned int cells, double bulk_over_shear, bool averaging);

/// The FE far field (Q1, one cell thick), explicit at its CFL or Newmark at T/80; with or
/// without the mean-dilatation F-bar; one_point: one point per cell with hourglass control
/// (explicit only).
ShearModeResult fe_shear_mode(unsigned int cells, double bulk_over_shear, bool averaging,
                              fem::TimeIntegrator integrator, bool one_point = false);
} // namespace vulnus::verification
