// Two-surface failure criterion of the tissue (paper eqs. 5-6): matrix failure by maximum
// shear strain, fiber failure by total fiber stretch; flags are irreversible.
#pragma once

#include "materials/material.h"
#include "materials/material_parameters.h"

#include <cstdint>

namespace vulnus::materials
{
/// Matrix shear measure from the eigenvalues e1 >= e2 >= e3 of C (or of B = F F^T, the same):
///   E1 - E3      = (e1 - e3) / 2      (principal Green-Lagrange strain difference, default)
///   (E1 - E3)/2  = (e1 - e3) / 4      (tensorial shear strain)
///   ln(l1 / l3)  = ln(e1 / e3) / 2    (logarithmic principal stretch ratio)
double matrix_shear_measure(ShearMeasure measure, const Vector3& eigenvalues_descending);

/// Failure state after checking the deformation F (fiber direction a0, unit) against the
/// limits: matrix when matrix_shear_measure > matrix_shear_limit (bit 0), fibers when
/// |F a0| > fiber_stretch_limit (bit 1, only if check_fibers). Bits already set stay set,
/// and a phase that has failed is not checked again. Eigenvalues (closed form) are computed
/// only for an intact matrix whose deviatoric norm leaves the decision open (the difference
/// measures are bounded by sqrt(3/2) |dev B| <= e1 - e3 <= sqrt(2) |dev B|); none at all
/// when failure is disabled, in which case old_flags is returned unchanged.
std::uint8_t updated_failure_flags(const FailureParameters& parameters, const Tensor2& F,
                                   const Vector3& a0, bool check_fibers, std::uint8_t old_flags);

/// The matrix shear measure at F (the parameters' choice), exactly.
double matrix_shear_at(const FailureParameters& parameters, const Tensor2& F);
/// An upper bound of matrix_shear_at without eigenvalues (sqrt(2) |dev B| times the factor
/// of the difference measures; the exact value for the logarithmic one).
double matrix_shear_bound(const FailureParameters& parameters, const Tensor2& F);

/// The flags after an update, given the byte the caller left: its failure bits plus, when it
/// set failure_decided_outside, the failures it decided (the *_fails_now bits); otherwise the
/// local criterion decides. The result holds the failure bits only.
std::uint8_t flags_after_update(const FailureParameters& parameters, const Tensor2& F,
                                const Vector3& a0, bool check_fibers, std::uint8_t byte);
} // namespace vulnus::materials
