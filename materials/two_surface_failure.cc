// Two-surface failure criterion: shear measures and the irreversible flag update.
#include "materials/two_surface_failure.h"

#include "materials/symmetric_eigenvalues.h"

#include <cmath>

namespace vulnus::materials
{
double matrix_shear_measure(const ShearMeasure measure, const Vector3& e)
{
  switch (measure)
  {
  case ShearMeasure::principal_green_difference:
    return 0.5 * (e[0] - e[2]);
  case ShearMeasure::half_principal_green_difference:
    return 0.25 * (e[0] - e[2]);
  case ShearMeasure::log_stretch_ratio:
    return 0.5 * std::log(e[0] / e[2]);
  }
  return 0.0;
}

std::uint8_t updated_failure_flags(const FailureParameters& parameters, const Tensor2& F,
                                   const Vector3& a0, const bool check_fibers,
                                   const std::uint8_t old_flags)
{
  if (!parameters.enabled)
    return old_flags;
  std::uint8_t flags = old_flags;
  if (!(flags & matrix_failed))
  {
    const Tensor2 B = F * F.transpose();
    if (parameters.shear_measure == ShearMeasure::log_stretch_ratio)
    {
      if (matrix_shear_measure(parameters.shear_measure, symmetric_eigenvalues(B)) >
          parameters.matrix_shear_limit)
        flags |= matrix_failed;
    }
    else
    {
      // Both difference measures are e1 - e3 times a factor. For the deviator D of B,
      // 3/2 |D|^2 <= (e1 - e3)^2 <= 2 |D|^2, so most points are decided without eigenvalues.
      const double factor =
          parameters.shear_measure == ShearMeasure::principal_green_difference ? 0.5 : 0.25;
      const double limit = parameters.matrix_shear_limit / factor; // on e1 - e3
      const double q = B.trace() / 3.0;
      const double deviator_squared = (B - q * Tensor2::Identity()).squaredNorm();
      if (1.5 * deviator_squared > limit * limit)
        flags |= matrix_failed;
      else if (2.0 * deviator_squared > limit * limit)
      {
        const Vector3 e = symmetric_eigenvalues(B);
        if (matrix_shear_measure(parameters.shear_measure, e) > parameters.matrix_shear_limit)
          flags |= matrix_failed;
      }
    }
  }
  if (check_fibers && !(flags & fiber_failed))
  {
    if ((F * a0).squaredNorm() > parameters.fiber_stretch_limit * parameters.fiber_stretch_limit)
      flags |= fiber_failed;
  }
  return flags;
}
double matrix_shear_at(const FailureParameters& parameters, const Tensor2& F)
{
  return matrix_shear_measure(parameters.shear_measure, symmetric_eigenvalues(F * F.transpose()));
}

double matrix_shear_bound(const FailureParameters& parameters, const Tensor2& F)
{
  if (parameters.shear_measure == ShearMeasure::log_stretch_ratio)
    return matrix_shear_at(parameters, F);
  const double factor =
      parameters.shear_measure == ShearMeasure::principal_green_difference ? 0.5 : 0.25;
  const Tensor2 B = F * F.transpose();
  const double q = B.trace() / 3.0;
  return factor * std::sqrt(2.0 * (B - q * Tensor2::Identity()).squaredNorm());
}

std::uint8_t flags_after_update(const FailureParameters& parameters, const Tensor2& F,
                                const Vector3& a0, const bool check_fibers,
                                const std::uint8_t byte)
{
  const std::uint8_t flags = byte & total_failure;
  if (byte & failure_decided_outside)
    return flags | ((byte >> 2) & total_failure);
  return updated_failure_flags(parameters, F, a0, check_fibers, flags);
}
} // namespace vulnus::materials
