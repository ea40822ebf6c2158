// Which points' failure measures pass their limits, for the nonlocal failure criterion
// (mpm/nonlocal_failure.h): a weighted mean passes a limit only near a point past it, so
// these flags decide where the means are needed. The deformation update sets them while it
// holds the new F, so the criterion need not read every point's F again.
#pragma once

#include "materials/material_parameters.h"
#include "materials/two_surface_failure.h"
#include "mpm/particles.h"

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
constexpr std::uint8_t shear_past_limit = 1;   ///< the matrix shear measure's bound
constexpr std::uint8_t stretch_past_limit = 2; ///< the fiber stretch

/// The fiber stretch |F a0| (a0 the unit fiber direction).
inline double fiber_stretch(const Tensor2& F, const Vector3f& fiber_direction)
{
  return (F * fiber_direction.cast<double>().normalized()).norm();
}

/// The limits the measures of F pass (shear_past_limit, stretch_past_limit), compared without
/// square roots and with room for rounding, so a point past a limit is never missed (the
/// limits are positive: the laws check them when a deck is read).
inline std::uint8_t limits_passed(const materials::FailureParameters& criterion,
                                  const bool fibers, const Tensor2& F,
                                  const Vector3f& fiber_direction)
{
  constexpr double room = 1.0 - 1e-12;
  std::uint8_t passed = 0;
  if (criterion.shear_measure == materials::ShearMeasure::log_stretch_ratio)
  {
    if (materials::matrix_shear_bound(criterion, F) > room * criterion.matrix_shear_limit)
      passed |= shear_past_limit;
  }
  else
  {
    // matrix_shear_bound = factor sqrt(2 |dev B|^2).
    const double factor =
      criterion.shear_measure == materials::ShearMeasure::principal_green_difference ? 0.5 : 0.25;
    const Tensor2 B = F * F.transpose();
    const double deviator_squared =
      (B - (B.trace() / 3.0) * Tensor2::Identity()).squaredNorm();
    const double limit = criterion.matrix_shear_limit;
    if (2.0 * factor * factor * deviator_squared > room * limit * limit)
      passed |= shear_past_limit;
  }
  if (fibers)
  {
    const double limit = criterion.fiber_stretch_limit;
    const Vector3 a = fiber_direction.cast<double>();
    if ((F * a).squaredNorm() > room * limit * limit * a.squaredNorm())
      passed |= stretch_past_limit;
  }
  return passed;
}

/// Flags per point, set by the deformation update for the bodies with a criterion.
struct FailureLimitFlags
{
  std::vector<const materials::FailureParameters*> criterion; ///< per body; nullptr: none
  std::vector<char> fibers;                                   ///< per body
  std::vector<char> filled; ///< per body: set at this step's deformation update
  std::vector<std::uint8_t> passed; ///< per point: limits_passed of its new F
};
} // namespace vulnus::mpm
