// Interface every constitutive law of vulnus implements; used alike by MPM particles and
// FE quadrature points. A material holds parameters only; per-point history lives in
// PointState, owned by the caller. Units SI (m, kg, s, Pa).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace vulnus::materials
{
using Tensor2 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;
/// d P_iJ / d F_kL as a 9x9 matrix, row 3*i+J, column 3*k+L (P the first Piola stress).
using Tangent = Eigen::Matrix<double, 9, 9>;

struct FailureParameters;

/// Failure flag of a point (paper eqs. 5-6): bit 0 matrix, bit 1 fibers.
enum FailureFlag : std::uint8_t
{
  intact = 0,
  matrix_failed = 1,
  fiber_failed = 2,
  total_failure = 3,
  /// Set by a caller that decides failure itself (the nonlocal criterion) just before an
  /// update, cleared by the update: the law then takes the two bits below as its new
  /// failures instead of checking its local criterion. Never seen outside that call.
  failure_decided_outside = 16,
  matrix_fails_now = 4,
  fibers_fail_now = 8
};

/// Plastic history of an elastic-plastic point (56 bytes).
struct PlasticHistory
{
  double equivalent_plastic_strain = 0.0;
  /// Inverse isochoric plastic right Cauchy-Green tensor C_p~^{-1} (det 1) in Voigt order xx
  /// yy zz xy yz xz. The trial state b_e~ = F~ C_p~^{-1} F~^T needs no previous F (it equals
  /// f b_e~_n f^T, f = F F_n^{-1}), and b_e~ itself need not be stored.
  std::array<double, 6> inverse_plastic_cauchy_green{{1.0, 1.0, 1.0, 0.0, 0.0, 0.0}};
};

/// History of one material point: irreversible failure flags and the plastic history (read
/// by the elastic-plastic law only). FE quadrature points and the point driver hold it whole;
/// MPM points keep the flags per point and a plastic history only where the law has one
/// (see PointBlock).
struct PointState
{
  std::uint8_t failure = intact;
  PlasticHistory plastic;
};

/// Where a point's plastic history sits in a pool of histories.
struct PlasticSlot
{
  static constexpr std::uint32_t none = 0xffffffffu;
  std::uint32_t index = none;
};

/// What one update returns.
struct PointResponse
{
  Tensor2 cauchy_stress = Tensor2::Zero();
  /// Stored energy per unit reference volume of the parts that have not failed (J/m^3).
  double energy_density = 0.0;
  /// Dilatational (P-wave) modulus of the current state in Pa, real and non-negative, so that
  /// the wave speed is sqrt(modulus / current density). Zero for a rigid body and for failed
  /// material that carries no wave (debris in tension).
  double p_wave_modulus = 0.0;
  /// Energy per unit reference volume dissipated in this update: plastic work, and the
  /// stored energy of a phase released at the moment it fails (J/m^3).
  double dissipated_density = 0.0;
  /// von Mises stress over current yield stress (elastic-plastic only, else 0).
  double von_mises_over_yield = 0.0;
};

/// Arrays (structure of arrays) of a block of points that share one material.
/// fiber_directions (single precision, normalized in double before use) may be null for
/// materials without fibers. The plastic history of point i
/// is plastic[plastic_slots[i].index]; both may be null for laws without plastic history.
struct PointBlock
{
  std::size_t n_points = 0;
  const Tensor2* deformation_gradients = nullptr;
  const Eigen::Vector3f* fiber_directions = nullptr;
  std::uint8_t* failure = nullptr;
  PlasticHistory* plastic = nullptr;
  const PlasticSlot* plastic_slots = nullptr;
  PointResponse* responses = nullptr;
  /// The step over which the deformation gradients were reached (s); 0 when unknown, and
  /// rate-dependent laws then use their rate-free strength.
  double time_step = 0.0;
};

class Material
{
public:
  virtual ~Material() = default;

  /// Registered model name, e.g. "transversely isotropic hyperelastic".
  virtual std::string model_name() const = 0;

  /// True for a body that moves rigidly: no stress update, no time-step limit.
  virtual bool is_rigid() const { return false; }
  /// True when the law uses a fiber direction.
  virtual bool uses_fibers() const { return false; }
  /// True when the law reads and writes PlasticHistory (else only the failure flags).
  virtual bool has_plastic_history() const { return false; }
  /// The two-surface failure criterion of the law, or null when it has none.
  virtual const FailureParameters* failure_criterion() const { return nullptr; }
  /// The von Mises stress (Pa) below which the law responds elastically, before any rate
  /// factor; 0 when the law has no such limit.
  virtual double elastic_limit_stress() const { return 0.0; }

  /// Update one point: F the total deformation gradient, a0 the unit reference fiber
  /// direction (ignored without fibers), reached over time_step from the stored state (0:
  /// unknown, rate-free). Updates the history in state.
  virtual void update(const Tensor2& F, const Vector3& a0, PointState& state,
                      PointResponse& response, double time_step) const = 0;
  /// The rate-free update (time_step 0), for drivers and checks without a time scale.
  void update(const Tensor2& F, const Vector3& a0, PointState& state,
              PointResponse& response) const
  {
    update(F, a0, state, response, 0.0);
  }

  /// Update a block of points: one virtual call per block, the loop inside is not virtual.
  /// Threading is the caller's (split the block).
  virtual void update_block(const PointBlock& block) const = 0;

  /// Consistent tangent dP/dF at (F, state) without changing the state (failure frozen,
  /// plastic flow as in the return map of an update from the stored state over time_step).
  virtual Tangent tangent(const Tensor2& F, const Vector3& a0, const PointState& state,
                          double time_step) const = 0;
  /// The rate-free tangent (time_step 0).
  Tangent tangent(const Tensor2& F, const Vector3& a0, const PointState& state) const
  {
    return tangent(F, a0, state, 0.0);
  }
};

/// Implements update_block for a concrete law through its non-virtual update_point,
/// so the per-point call inlines (CRTP).
template <class Law> class MaterialBase : public Material
{
public:
  using Material::tangent;
  using Material::update;

  void update(const Tensor2& F, const Vector3& a0, PointState& state, PointResponse& response,
              const double time_step) const final
  {
    static_cast<const Law&>(*this).update_point(F, a0, state.failure, state.plastic, response,
                                                time_step);
  }

  void update_block(const PointBlock& block) const final
  {
    const Law& law = static_cast<const Law&>(*this);
    if (law.has_plastic_history() && !(block.plastic && block.plastic_slots))
      throw std::invalid_argument(law.model_name() +
                                  ": a block of points without their plastic history");
    static const Vector3 no_fiber = Vector3::UnitX();
    PlasticHistory unused; // laws without plastic history never touch it
    for (std::size_t i = 0; i < block.n_points; ++i)
      law.update_point(block.deformation_gradients[i],
                       block.fiber_directions
                         ? Vector3(block.fiber_directions[i].cast<double>().normalized())
                         : no_fiber,
                       block.failure[i],
                       block.plastic ? block.plastic[block.plastic_slots[i].index] : unused,
                       block.responses[i], block.time_step);
  }
};
} // namespace vulnus::materials
