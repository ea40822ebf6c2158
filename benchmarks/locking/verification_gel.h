// The isotropic, elastic gel of the locking verification problems (shear mode, Lame cylinder):
// mu = 20 kPa, K = bulk_over_shear mu, no fibres, no failure.
#pragma once

#include "materials/material_parameters.h"

namespace vulnus::verification
{
inline constexpr double verification_gel_shear_modulus = 2e4; ///< Pa, mu = 2 c1

inline materials::MaterialParameters verification_gel(const double bulk_over_shear)
{
  materials::MaterialParameters m;
  m.model = "isotropic hyperelastic";
  m.tissue.with_fibers = false;
  m.tissue.c1 = 0.5 * verification_gel_shear_modulus;
  m.tissue.c2 = 0.0;
  m.tissue.bulk_modulus = bulk_over_shear * verification_gel_shear_modulus;
  m.tissue.failure.enabled = false;
  return m;
}
} // namespace vulnus::verification
