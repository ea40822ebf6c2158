// Stress-update stage: every deformable body's material updates its points in blocks (one
// virtual call per block; rigid bodies are skipped, failed points keep whatever their law
// leaves them), then the optional artificial bulk viscosity is added.
#pragma once

#include "materials/material.h"
#include "materials/shock_viscosity.h"
#include "mpm/grid.h"
#include "mpm/particles.h"

#include <vector>

namespace vulnus::mpm
{
struct StressUpdateSettings
{
  double time_step = 0.0;
  double cell_size = 0.0;
  /// A graded grid: the viscosity's length is then the widest side of each point's cell.
  const Grid* graded_grid = nullptr;
  /// Bulk viscosity q = rho (linear c h |tr D| + quadratic h^2 tr(D)^2) in compression.
  materials::ShockViscosity viscosity;
  bool uses_viscosity() const { return viscosity.active(); }
  std::vector<const materials::Material*> body_material;
  std::vector<double> body_density; ///< reference density per body, kg/m^3
  /// Per body, 1 when another stepper updates its points (a subcycled projectile). Empty: none.
  std::vector<char> body_advanced_elsewhere;
};

struct StressUpdateResult
{
  std::vector<double> max_von_mises_over_yield; ///< per body
  double viscous_dissipation = 0.0;             ///< J this step
  /// First point whose update failed (material threw), or -1; with its message.
  long failed_point = -1;
  std::string failure_message;
};

/// volumetric_rate (per point, ln(J_new / J_old) / dt) may be null when the viscosity is off.
void update_stresses(const StressUpdateSettings& settings,
                     const double* volumetric_rate, Particles& particles,
                     StressUpdateResult& result);
} // namespace vulnus::mpm
