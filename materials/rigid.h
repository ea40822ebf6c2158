// Rigid material: a body that moves with prescribed or contact-driven rigid motion; no stress
// update and no time-step limit (docs/DESIGN.md section 3, bullet option).
#pragma once

#include "materials/material.h"

namespace vulnus::materials
{
/// Infinitely stiff body: zero stress, zero energy, p_wave_modulus 0 (the solver excludes
/// rigid bodies from the CFL limit via is_rigid()), zero tangent. The state is untouched.
class Rigid final : public MaterialBase<Rigid>
{
public:
  std::string model_name() const override { return "rigid"; }
  bool is_rigid() const override { return true; }

  using Material::tangent;

  void update_point(const Tensor2&, const Vector3&, std::uint8_t&, PlasticHistory&,
                    PointResponse& response, double) const
  {
    response = PointResponse();
  }

  Tangent tangent(const Tensor2&, const Vector3&, const PointState&, double) const override
  {
    return Tangent::Zero();
  }
};
} // namespace vulnus::materials
