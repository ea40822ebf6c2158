// Whole-scene diagnostics of an MPM state: energies, momentum, failure counts and the
// projectile's kinematics, reduced over the points with threads.
#pragma once

#include "mpm/particles.h"

#include <array>
#include <vector>

namespace vulnus::mpm
{
struct BodySummary
{
  double mass = 0.0;
  Vector3 centroid = Vector3::Zero();
  Vector3 velocity = Vector3::Zero(); ///< mass-averaged
  double kinetic_energy = 0.0;
  double strain_energy = 0.0;
  double dissipated_energy = 0.0; ///< material dissipation (failure, plasticity, viscosity)
  /// Extent of the body's points along a direction: min and max of x . direction.
  double min_along = 0.0;
  double max_along = 0.0;
};

struct SceneDiagnostics
{
  double kinetic_energy = 0.0;
  double strain_energy = 0.0;
  double potential_energy = 0.0; ///< -sum m g . x
  double dissipated_energy = 0.0; ///< material + viscous, accumulated since the start
  Vector3 momentum = Vector3::Zero();
  /// Points whose failure flag is 0 intact, 1 matrix, 2 fibers, 3 total.
  std::array<std::size_t, 4> failure_counts{{0, 0, 0, 0}};
  std::vector<BodySummary> bodies;
};

/// Reduces the state; `direction` is the axis along which body extents are measured.
SceneDiagnostics compute_diagnostics(const Particles& particles, const Vector3& direction,
                                     const Vector3& gravity);
} // namespace vulnus::mpm
