// Weiss 1996 tissue law with two-surface failure: stress, energy, wave modulus, tangent,
// and its registration under "transversely isotropic hyperelastic" / "isotropic hyperelastic".
#include "materials/transversely_isotropic_hyperelastic.h"

#include "materials/cofactor.h"
#include "materials/dual_number.h"
#include "materials/material_registry.h"
#include "materials/two_surface_failure.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::materials
{
namespace
{
template <typename Scalar> using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;

void throw_inverted(const double J)
{
  std::ostringstream message;
  message << "tissue material: det F = " << J
          << " <= 0 (inverted or degenerate element/particle); reduce the time step or "
             "refine the resolution";
  throw std::runtime_error(message.str());
}
} // namespace

template <bool with_fibers>
TissueHyperelastic<with_fibers>::TissueHyperelastic(const TissueParameters& parameters)
    : prm(parameters), fibers(with_fibers ? parameters.c3 : 0.0, parameters.c4,
                              with_fibers ? parameters.c5 : 0.0, parameters.lambda_star),
      volumetric(parameters), small_strain_shear_modulus(2.0 * (parameters.c1 + parameters.c2)),
      failed_carries_nothing(parameters.failure.stress_after_failure == StressAfterFailure::zero)
{
  prm.with_fibers = with_fibers;
}

template <bool with_fibers> std::string TissueHyperelastic<with_fibers>::model_name() const
{
  return with_fibers ? "transversely isotropic hyperelastic" : "isotropic hyperelastic";
}

template <bool with_fibers>
template <typename Scalar>
void TissueHyperelastic<with_fibers>::kirchhoff_parts(const Matrix3<Scalar>& F, const Vector3& a0,
                                                      const std::uint8_t failure_flags,
                                                      Matrix3<Scalar>& tau_volumetric,
                                                      Matrix3<Scalar>& tau_matrix,
                                                      Matrix3<Scalar>& tau_fibers,
                                                      TissueStressParts* energies) const
{
  using std::cbrt;
  using std::sqrt;
  const Matrix3<Scalar> identity = Matrix3<Scalar>::Identity();
  const Scalar J = F.determinant();
  const Scalar J_minus_third = 1.0 / cbrt(J);
  tau_volumetric.setZero();
  tau_matrix.setZero();
  tau_fibers.setZero();
  if (energies)
    energies->J = value_of(J);

  const bool matrix_intact = !(failure_flags & matrix_failed);
  if (matrix_intact)
  {
    tau_volumetric = volumetric.kirchhoff_pressure_term(J) * identity;
    const Matrix3<Scalar> B_bar = (J_minus_third * J_minus_third) * (F * F.transpose());
    const Scalar I1 = B_bar.trace();
    if (energies)
      energies->first_invariant = value_of(I1);
    if (prm.c2 != 0.0)
    {
      const Matrix3<Scalar> B_bar_2 = B_bar * B_bar;
      const Scalar I2 = 0.5 * (I1 * I1 - B_bar_2.trace());
      tau_matrix = 2.0 * ((prm.c1 + prm.c2 * I1) * B_bar - prm.c2 * B_bar_2 -
                          ((prm.c1 * I1 + 2.0 * prm.c2 * I2) / 3.0) * identity);
      if (energies)
        energies->matrix_energy = value_of(prm.c1 * (I1 - 3.0) + prm.c2 * (I2 - 3.0));
    }
    else
    {
      tau_matrix = (2.0 * prm.c1) * (B_bar - (I1 / 3.0) * identity);
      if (energies)
        energies->matrix_energy = prm.c1 * (value_of(I1) - 3.0);
    }
    if (energies)
      energies->volumetric_energy = volumetric.energy(value_of(J));
  }
  else if (!failed_carries_nothing && value_of(J) < 1.0)
  {
    // Failed tissue is debris: it keeps the pressure of the volumetric law in compression
    // (U(J) for J < 1, 0 beyond: C1 at J = 1), so it is never crushed.
    tau_volumetric = volumetric.kirchhoff_pressure_term(J) * identity;
    if (energies)
      energies->volumetric_energy = volumetric.energy(value_of(J));
  }

  if constexpr (with_fibers)
  {
    // Intact matrix: the uncoupled form on the deviatoric stretch, whose -f/3 I the matrix's
    // pressure balances. Failed matrix (debris rule): nothing balances it, so the fibers carry
    // their uniaxial stress f a (x) a on the total stretch |F a0| (W = F2(lambda), tau = f a
    // (x) a). The zero rule keeps the intact form, as Uintah's TransIsoHyper does.
    const bool uncoupled = matrix_intact || failed_carries_nothing;
    const Eigen::Matrix<Scalar, 3, 1> Fa =
        uncoupled ? Eigen::Matrix<Scalar, 3, 1>(J_minus_third * (F * a0.cast<Scalar>()))
                  : Eigen::Matrix<Scalar, 3, 1>(F * a0.cast<Scalar>());
    const Scalar I4 = Fa.dot(Fa);
    const Scalar lambda = sqrt(I4);
    if (energies)
      energies->fiber_stretch = value_of(lambda);
    if (!(failure_flags & fiber_failed) && lambda > Scalar(1.0))
    {
      const Scalar f = fibers.force(lambda);
      tau_fibers = (f / I4) * (Fa * Fa.transpose());
      if (uncoupled)
        tau_fibers -= (f / 3.0) * identity;
      if (energies)
        energies->fiber_energy = fibers.energy(value_of(lambda));
    }
  }
}

template <bool with_fibers>
template <typename Scalar>
Eigen::Matrix<Scalar, 3, 3>
TissueHyperelastic<with_fibers>::first_piola_stress(const Matrix3<Scalar>& F, const Vector3& a0,
                                                    const std::uint8_t failure_flags) const
{
  const double J = value_of(F.determinant());
  if (!(J > 0.0))
    throw_inverted(J);
  Matrix3<Scalar> tau_v, tau_m, tau_f;
  kirchhoff_parts(F, a0, failure_flags, tau_v, tau_m, tau_f, nullptr);
  // P = tau F^{-T} = tau cof(F) / J.
  return (tau_v + tau_m + tau_f) * cofactor(F) / F.determinant();
}

template <bool with_fibers>
TissueStressParts TissueHyperelastic<with_fibers>::stress_parts(const Tensor2& F, const Vector3& a0,
                                                                const std::uint8_t flags) const
{
  const double J = F.determinant();
  if (!(J > 0.0))
    throw_inverted(J);
  TissueStressParts parts;
  kirchhoff_parts(F, a0, flags, parts.volumetric, parts.matrix, parts.fibers, &parts);
  parts.volumetric /= J;
  parts.matrix /= J;
  parts.fibers /= J;
  return parts;
}

template <bool with_fibers>
double TissueHyperelastic<with_fibers>::wave_modulus(const double J, const double I1,
                                                     const double lambda,
                                                     const std::uint8_t flags) const
{
  double modulus = 0.0;
  const bool matrix_intact = !(flags & matrix_failed);
  if (matrix_intact || (J < 1.0 && !failed_carries_nothing))
    modulus += std::max(volumetric.tangent_bulk_modulus(J), 0.0);
  if (matrix_intact)
    modulus += 4.0 / 3.0 * 2.0 * (prm.c1 + prm.c2 * I1) * I1 / (3.0 * J);
  if constexpr (with_fibers)
  {
    if (!(flags & fiber_failed) && lambda > 1.0)
      modulus += (fibers.stiffness(lambda) + fibers.force(lambda)) / J;
  }
  // An intact point never reports less than its small-strain shear wave; failed debris in
  // tension carries no wave at all and limits the step by its speed alone.
  return matrix_intact ? std::max(modulus, 4.0 / 3.0 * small_strain_shear_modulus) : modulus;
}

template <bool with_fibers>
double TissueHyperelastic<with_fibers>::p_wave_modulus(const Tensor2& F, const Vector3& a0,
                                                       const std::uint8_t flags) const
{
  const double J = F.determinant();
  if (!(J > 0.0))
    throw_inverted(J);
  const double J_minus_third = 1.0 / std::cbrt(J);
  const double I1 = J_minus_third * J_minus_third * F.squaredNorm();
  const double fiber_scale =
      (flags & matrix_failed) && !failed_carries_nothing ? 1.0 : J_minus_third;
  const double lambda = with_fibers ? fiber_scale * (F * a0).norm() : 1.0;
  return wave_modulus(J, I1, lambda, flags);
}

template <bool with_fibers>
void TissueHyperelastic<with_fibers>::update_point(const Tensor2& F, const Vector3& a0,
                                                   std::uint8_t& failure, PlasticHistory&,
                                                   PointResponse& response, double) const
{
  const double J = F.determinant();
  if (!(J > 0.0) || !std::isfinite(J))
    throw_inverted(J);

  const std::uint8_t old_flags = failure & total_failure;
  std::uint8_t flags = flags_after_update(prm.failure, F, a0, with_fibers, failure);
  if (!with_fibers && (flags & matrix_failed))
    flags |= fiber_failed; // without fibers the failed matrix leaves nothing: total failure
  const std::uint8_t newly_failed = flags & ~old_flags;

  TissueStressParts parts;
  kirchhoff_parts(F, a0, flags, parts.volumetric, parts.matrix, parts.fibers, &parts);

  // A phase that fails releases its stored energy: the energy at F before the failure minus
  // what the surviving parts store (the failed-matrix fibers measure the total stretch).
  double dissipated = 0.0;
  if (newly_failed)
  {
    TissueStressParts before;
    kirchhoff_parts(F, a0, old_flags, before.volumetric, before.matrix, before.fibers, &before);
    dissipated = before.total_energy() - parts.total_energy();
  }

  failure = flags;
  response.cauchy_stress = (parts.volumetric + parts.matrix + parts.fibers) / J;
  response.energy_density = parts.volumetric_energy + parts.matrix_energy + parts.fiber_energy;
  response.dissipated_density = dissipated;
  response.von_mises_over_yield = 0.0;
  response.p_wave_modulus = wave_modulus(J, parts.first_invariant, parts.fiber_stretch, flags);
}

template <bool with_fibers>
Tangent TissueHyperelastic<with_fibers>::tangent(const Tensor2& F, const Vector3& a0,
                                                 const PointState& state, double) const
{
  Tangent D;
  const Matrix3<Dual> F_dual = F.cast<Dual>();
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
      Matrix3<Dual> F_seeded = F_dual;
      F_seeded(k, L).d = 1.0;
      const Matrix3<Dual> P = first_piola_stress(F_seeded, a0, state.failure);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          D(3 * i + j, 3 * k + L) = P(i, j).d;
    }
  return D;
}

template class TissueHyperelastic<true>;
template class TissueHyperelastic<false>;
template Eigen::Matrix<double, 3, 3>
TissueHyperelastic<true>::first_piola_stress(const Matrix3<double>&, const Vector3&,
                                             std::uint8_t) const;
template Eigen::Matrix<double, 3, 3>
TissueHyperelastic<false>::first_piola_stress(const Matrix3<double>&, const Vector3&,
                                              std::uint8_t) const;

namespace
{
void check_tissue(const MaterialParameters& parameters, const bool with_fibers,
                  std::vector<ParameterProblem>& problems)
{
  const TissueParameters& t = parameters.tissue;
  auto require = [&](const bool ok, const std::string& entry, const double value,
                     const std::string& problem, const std::string& remedy)
  {
    if (!ok)
    {
      std::ostringstream got;
      got << problem << " (got " << value << ")";
      problems.push_back({{entry}, got.str(), remedy});
    }
  };
  auto finite = [](const double x) { return std::isfinite(x); };
  require(finite(t.c1) && t.c1 > 0.0, "c1", t.c1, "must be positive",
          "give the Mooney-Rivlin constant in Pa, e.g. 2100");
  require(finite(t.c2) && t.c2 >= 0.0, "c2", t.c2, "must be zero or positive",
          "give the second Mooney-Rivlin constant in Pa, e.g. 0");
  require(finite(t.bulk_modulus) && t.bulk_modulus > 0.0, "Bulk modulus", t.bulk_modulus,
          "must be positive", "give K in Pa, e.g. 200e3");
  if (t.volumetric_law == VolumetricLawKind::hugoniot)
    require(finite(t.hugoniot_slope) && t.hugoniot_slope >= 0.5 && t.hugoniot_slope <= 4.0,
            "Hugoniot slope", t.hugoniot_slope, "must lie in [0.5, 4]",
            "give s of the shock Hugoniot Us = c0 + s up, e.g. 2 for 10 % gelatin");
  if (with_fibers)
  {
    require(finite(t.c3) && t.c3 >= 0.0, "c3", t.c3, "must be zero or positive",
            "give the toe-region scale in Pa, e.g. 140");
    require(finite(t.c4) && t.c4 > 0.0 && t.c4 < 700.0, "c4", t.c4,
            "must be positive and below 700", "give the uncrimping rate, e.g. 22");
    require(finite(t.c5) && t.c5 >= 0.0, "c5", t.c5, "must be zero or positive",
            "give the straightened-fiber modulus in Pa, e.g. 100e3");
    require(finite(t.lambda_star) && t.lambda_star >= 1.0 && t.lambda_star < 10.0, "Lambda star",
            t.lambda_star, "must be at least 1 (and below 10)",
            "give the stretch where fibers straighten, e.g. 1.4");
  }
  if (t.failure.enabled)
  {
    require(finite(t.failure.matrix_shear_limit) && t.failure.matrix_shear_limit > 0.0,
            "Failure/Matrix shear limit", t.failure.matrix_shear_limit, "must be positive",
            "give the critical shear strain, e.g. 0.5, or disable failure");
    if (with_fibers)
      require(finite(t.failure.fiber_stretch_limit) && t.failure.fiber_stretch_limit > 1.0,
              "Failure/Fiber stretch limit", t.failure.fiber_stretch_limit, "must be greater than 1",
              "give the critical total fiber stretch, e.g. 1.4, or disable failure");
    require(finite(t.failure.regularization_length) && t.failure.regularization_length >= 0.0 &&
              t.failure.regularization_length < 1.0,
            "Failure/Regularization length", t.failure.regularization_length,
            "must be at least 0 and below 1 m",
            "give the material length in metres, e.g. 0.002, or 0 for the local criterion");
  }
}

const std::string common_documentation =
    " W = c1 (I1~ - 3) + c2 (I2~ - 3) + U(J) [+ F2(lambda~)]; entries c1, c2 (Pa), "
    "Bulk modulus (Pa), Volumetric law (logarithmic: U = K/2 (ln J)^2; Hugoniot: compression "
    "on the shock Hugoniot Us = c0 + s up, c0^2 = K/rho0, entry Hugoniot slope s); two-surface failure (paper eqs. 5-6): Matrix shear limit (default 0.5, "
    "measure E1-E3, (E1-E3)/2 or ln(l1/l3)) zeroes matrix stress and tension pressure (failed "
    "tissue keeps its pressure in compression; the fibers of a failed matrix carry f a (x) a on "
    "the total stretch), Fiber stretch limit (default 1.4, total stretch |F a0|) zeroes fiber "
    "stress; flags 0 intact, 1 matrix, 2 fibers, 3 total. Stress after failure = zero "
    "applies the paper's rule instead: a failed matrix carries no matrix stress and no "
    "pressure, total failure nothing.";

const bool transversely_isotropic_registered = register_material_model(
    "transversely isotropic hyperelastic",
    "Weiss 1996 uncoupled transversely isotropic hyperelastic tissue (myocardium): Mooney-Rivlin "
    "matrix plus fibers along a0 with lambda dF2/dlambda = c3 (exp(c4 (lambda-1)) - 1) up to "
    "Lambda star, c5 lambda + c6 beyond, none in compression; entries c3 (Pa), c4, c5 (Pa), "
    "Lambda star." +
        common_documentation + " With fibers switched off it is the isotropic variant.",
    [](const MaterialParameters& parameters) -> std::unique_ptr<Material>
    {
      if (parameters.tissue.with_fibers)
        return std::make_unique<TransverselyIsotropicHyperelastic>(parameters.tissue);
      return std::make_unique<IsotropicHyperelastic>(parameters.tissue);
    },
    [](const MaterialParameters& parameters, std::vector<ParameterProblem>& problems)
    { check_tissue(parameters, parameters.tissue.with_fibers, problems); });

const bool isotropic_registered = register_material_model(
    "isotropic hyperelastic",
    "Isotropic variant of the tissue law (no fiber term, no fiber work): uncoupled Mooney-Rivlin "
    "with the same volumetric energy." +
        common_documentation,
    [](const MaterialParameters& parameters) -> std::unique_ptr<Material>
    { return std::make_unique<IsotropicHyperelastic>(parameters.tissue); },
    [](const MaterialParameters& parameters, std::vector<ParameterProblem>& problems)
    { check_tissue(parameters, false, problems); });
} // namespace
} // namespace vulnus::materials
