// The two analytic eigenmodes of a nearly incompressible square between rollers (plane strain),
// the locking verification of tests and benchmarks/locking. A square of side L = pi / k:
// * shear: u = A (sin kx cos ky, -cos kx sin ky, 0), divergence-free, rings at
//   T = 2 pi / (k sqrt(2) c_s) whatever the bulk modulus; its exact pressure is zero to first
//   order in the strain (of order mu (A k)^2 at finite strain), so a larger pressure is the
//   discretisation's volumetric error.
// * dilatation: u = A (sin kx cos ky, cos kx sin ky, 0), irrotational, rings at
//   T = 2 pi / (k sqrt(2) c_p), c_p^2 = (K + 4 mu / 3) / rho; it carries the pressure
//   p = -K div u, of amplitude 2 K A k.
// Started as a velocity field of strain amplitude A k (1e-4 unless given); the period is
// measured from the first two zero crossings of the modal velocity (at T/4 and 3T/4), the
// pressure at the first (the largest displacement).
#pragma once

#include "fem/fem_parameters.h"
#include "mpm/scene_parameters.h"

namespace vulnus::verification
{
enum class SquareMode
{
  shear,
  dilatation
};

struct SquareModeResult
{
  double period_ratio = 0.0; ///< measured over analytic period (0: fewer than two crossings)
  /// Root mean square over the cells of (the cell's volume-averaged pressure - the exact
  /// pressure at its centre) at T/4, over the mode's largest stress amplitude (shear:
  /// 2 mu A k; dilatation: 2 K A k).
  double pressure_error = 0.0;
  /// The mean of those cell errors (signed), over the same amplitude: the part of the error
  /// that is uniform over the square.
  double mean_pressure_error = 0.0;
  /// MPM only (FE: 0): the same at the points, each against the exact pressure where it is.
  double point_pressure_error = 0.0;
  unsigned long steps = 0;
  double seconds = 0.0; ///< wall time of the run
};

/// The MPM points' volume change: each its own, their cell's summed (cell J) or their cell's
/// grid-velocity flux (Grid/Volume averaging = grid flux).
enum class PointVolume
{
  own,
  cell,
  grid_flux
};

/// MPM, linear shape functions, 2 x 2 x 2 points per cell, MUSL, CFL 0.4, a square of
/// `cells` cells per side and two cells thick.
SquareModeResult
mpm_square_mode(SquareMode mode, unsigned int cells, double bulk_over_shear, PointVolume volume,
                double strain = 1e-4,
                mpm::VelocityTransfer transfer = mpm::VelocityTransfer::flip);

/// The FE far field (Q1, one cell thick), explicit at its CFL or Newmark at T/80; with or
/// without the mean-dilatation F-bar; one_point: one point per cell with hourglass control
/// (explicit only).
SquareModeResult fe_square_mode(SquareMode mode, unsigned int cells, double bulk_over_shear,
                                bool averaging, fem::TimeIntegrator integrator,
                                bool one_point = false, double strain = 1e-4);
} // namespace vulnus::verification
