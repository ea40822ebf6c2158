// The failing transversely isotropic hyperelastic tissue law (Weiss 1996, uncoupled) and its
// isotropic variant, shared by MPM particles and FE quadrature points (docs/DESIGN.md section 3).
#pragma once

#include "materials/material.h"
#include "materials/material_parameters.h"
#include "materials/volumetric_law.h"
#include "materials/weiss_fiber_law.h"

#include <cstdint>

namespace vulnus::materials
{
/// Stress and energy of each part of the tissue law at one state: Cauchy stresses (Pa) and
/// energies per unit reference volume (J/m^3), as the failure flags leave them (a failed
/// matrix keeps pressure in compression and gives its fibers the total stretch).
struct TissueStressParts
{
  Tensor2 volumetric = Tensor2::Zero();
  Tensor2 matrix = Tensor2::Zero();
  Tensor2 fibers = Tensor2::Zero();
  double volumetric_energy = 0.0;
  double matrix_energy = 0.0;
  double fiber_energy = 0.0;
  /// Fiber stretch the fiber stress uses: deviatoric lambda~ = sqrt(a0 . C~ a0) while the
  /// matrix is intact, total |F a0| once it has failed.
  double fiber_stretch = 1.0;
  /// Kinematic by-products reused for the wave modulus.
  double J = 1.0;
  double first_invariant = 3.0; ///< I1~

  Tensor2 total() const { return volumetric + matrix + fibers; }
  double total_energy() const { return volumetric_energy + matrix_energy + fiber_energy; }
};

/// Weiss, Maker & Govindjee (1996), uncoupled transversely isotropic hyperelasticity, with
/// the two-surface failure of the paper (eqs. 5-6). With J = det F, B~ = J^{-2/3} F F^T,
/// I1~ = tr B~, I2~ = (I1~^2 - tr B~^2)/2, lambda~ = |J^{-1/3} F a0|, a = J^{-1/3} F a0 / lambda~:
///
///   W = c1 (I1~ - 3) + c2 (I2~ - 3) + F2(lambda~) + U(J)
///   sigma_vol    = U'(J) I  (U = K/2 (ln J)^2, or the Hugoniot law: VolumetricLaw)
///   sigma_matrix = (2/J) [(c1 + c2 I1~) B~ - c2 B~^2 - (c1 I1~ + 2 c2 I2~)/3 I]
///   sigma_fibers = (1/J) f(lambda~) (a (x) a - I/3),   f = lambda dF2/dlambda (WeissFiberLaw)
///
/// Fibers carry no compression (f = 0 for lambda~ < 1). Failure (irreversible, flags in
/// PointState::failure): a failed matrix zeroes sigma_matrix, and sigma_vol in tension (failed
/// tissue is debris that still resists compression: sigma_vol = U'(J) I for J < 1); its
/// fibers then carry their full uniaxial stress (1/J) f(lambda) a (x) a on the total stretch
/// lambda = |F a0| (nothing balances the -f/3 I of the uncoupled form once the matrix is gone).
/// Failed fibers zero sigma_fibers. energy_density counts only what the surviving parts store;
/// dissipated_density is the stored energy lost at the update where a phase fails.
/// SI units: Pa, J/m^3.
///
/// The template flag selects the fiber code path at compile time: with_fibers = false is the
/// isotropic Mooney-Rivlin variant ("isotropic hyperelastic"), which does no fiber work.
///
/// P-wave modulus (time step): M = max(K_t, 0) + 4/3 G_t + (lambda f' + f)/J, with
/// K_t = J U''(J) (logarithmic: K (1 - ln J)/J, negative for J > e, hence clamped),
/// G_t = 2 (c1 + c2 I1~) I1~ / (3 J) and the fiber term while fibers are intact and
/// stretched; an intact point never reports less than 4/3 mu0, mu0 = 2 (c1 + c2). A failed
/// matrix keeps K_t only in compression and drops G_t: debris in tension has no wave.
/// det F <= 0 throws std::runtime_error.
template <bool with_fibers>
class TissueHyperelastic final : public MaterialBase<TissueHyperelastic<with_fibers>>
{
public:
  explicit TissueHyperelastic(const TissueParameters& parameters);

  std::string model_name() const override;
  bool uses_fibers() const override { return with_fibers; }
  const FailureParameters* failure_criterion() const override
  {
    return prm.failure.enabled ? &prm.failure : nullptr;
  }

  using Material::tangent;

  /// The law is rate-free: the time step is not used.
  void update_point(const Tensor2& F, const Vector3& a0, std::uint8_t& failure,
                    PlasticHistory& unused, PointResponse& response, double time_step) const;

  /// Exact dP/dF (forward-mode dual numbers through the stress) with the failure flags
  /// of state frozen.
  Tangent tangent(const Tensor2& F, const Vector3& a0, const PointState& state,
                  double time_step) const override;

  /// Parts of the stress and energy at F with the given failure flags (no failure check).
  TissueStressParts stress_parts(const Tensor2& F, const Vector3& a0,
                                 std::uint8_t failure_flags = intact) const;

  /// First Piola stress P = J sigma F^{-T} with given flags; Scalar is double or Dual.
  template <typename Scalar>
  Eigen::Matrix<Scalar, 3, 3> first_piola_stress(const Eigen::Matrix<Scalar, 3, 3>& F,
                                                 const Vector3& a0,
                                                 std::uint8_t failure_flags) const;

  /// P-wave modulus M (Pa) of the state F with the given flags (see class comment).
  double p_wave_modulus(const Tensor2& F, const Vector3& a0, std::uint8_t failure_flags) const;

  const TissueParameters& parameters() const { return prm; }
  const WeissFiberLaw& fiber_law() const { return fibers; }

private:
  template <typename Scalar>
  void kirchhoff_parts(const Eigen::Matrix<Scalar, 3, 3>& F, const Vector3& a0,
                       std::uint8_t failure_flags, Eigen::Matrix<Scalar, 3, 3>& tau_volumetric,
                       Eigen::Matrix<Scalar, 3, 3>& tau_matrix,
                       Eigen::Matrix<Scalar, 3, 3>& tau_fibers, TissueStressParts* energies) const;

  double wave_modulus(double J, double I1, double lambda, std::uint8_t flags) const;

  TissueParameters prm;
  WeissFiberLaw fibers;
  VolumetricLaw volumetric;
  double small_strain_shear_modulus; ///< mu0 = 2 (c1 + c2)
  bool failed_carries_nothing; ///< Failure/Stress after failure = zero (the paper's rule)
};

using TransverselyIsotropicHyperelastic = TissueHyperelastic<true>;
using IsotropicHyperelastic = TissueHyperelastic<false>;

extern template class TissueHyperelastic<true>;
extern template class TissueHyperelastic<false>;
} // namespace vulnus::materials
