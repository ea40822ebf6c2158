// The thick-walled cylinder (Lame) of the locking verification (tests and benchmarks/locking):
// a half annulus a <= r <= b, 0 <= theta <= pi, in plane strain (rollers on the end faces and
// on the cut plane y = 0), its inner surface pushed out by u_r(a) = delta, its outer surface
// free. Linear elasticity gives u_r = A r + B / r with A = mu B / ((lambda + mu) b^2) (B / r
// taken at finite strain, see the .cc), a
// pressure that is uniform through the wall and tends to a finite limit as K / mu grows,
// sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2 and sigma_tt = 2 (lambda + mu) A + 2 mu B / r^2.
// The far field takes one implicit step long enough that inertia is negligible (the static
// answer) at a strain of 1e-5, where the hyperelastic law is linear to that order.
#pragma once

#include "fem/fem_parameters.h"

namespace vulnus::verification
{
struct LameResult
{
  unsigned int radial_cells = 0;
  unsigned long long cells = 0;
  /// Root mean square over the nodes of |u - u_exact|, over that of |u_exact|.
  double displacement_error = 0.0;
  /// Root mean square over the cells of the centre's exact value minus the cell's
  /// volume-averaged Cauchy stress, over the exact inner radial stress |sigma_rr(a)|: the
  /// mean pressure, and the radial and hoop stresses.
  double pressure_error = 0.0;
  double radial_stress_error = 0.0;
  double hoop_stress_error = 0.0;
  double mean_pressure = 0.0;  ///< Pa, volume mean of the cells' pressure
  double exact_pressure = 0.0; ///< Pa
  unsigned int newton_iterations = 0;
  double seconds = 0.0;
};

/// The half annulus a = 5 mm, b = 10 mm, one cell thick, with `radial_cells` cells through the
/// wall and cells about square at mid-wall; the isotropic hyperelastic law with mu = 20 kPa and
/// K = bulk_over_shear mu; Q1 (degree 1) or Q2 with each point's own J, or Q1 with the
/// cell's (F-bar, volume_averaging).
LameResult lame_cylinder(unsigned int radial_cells, double bulk_over_shear, bool volume_averaging,
                         unsigned int degree = 1);
} // namespace vulnus::verification
