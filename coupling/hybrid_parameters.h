// Deck-level description of a hybrid MPM-FE scene (docs/DESIGN.md section 6): the MPM zone around
// the tract, which body it splits, and the coupling scheme. SI units.
#pragma once

#include <array>
#include <string>

namespace vulnus::coupling
{
enum class CouplingScheme
{
  same_step, ///< scheme 1: one time step, interface nodes shared (masses and forces summed)
  multi_step ///< scheme 2: the FE side takes steps of several MPM substeps
};

struct HybridParameters
{
  bool enabled = false;
  /// The MPM zone, a box on MPM grid nodes; the rest of the split body is finite elements.
  std::array<double, 3> zone_min{{0.0, 0.0, 0.0}};
  std::array<double, 3> zone_max{{0.0, 0.0, 0.0}};
  /// Name of the body split into MPM zone and FE far field; empty: the only deformable box
  /// body that is not the projectile.
  std::string body;
  CouplingScheme scheme = CouplingScheme::same_step;
  /// multi_step: MPM substeps per FE step; 0 chooses the FE step from its own stability
  /// (explicit) or the deck step (implicit).
  unsigned int substeps = 0;
  /// A failed far-field quadrature point stops the run (else it warns and goes on).
  bool stop_when_fe_points_fail = true;
};
} // namespace vulnus::coupling
