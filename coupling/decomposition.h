// Splits a scene into the MPM zone (particles) and the FE far field (graded mesh with a hole),
// and checks before any work that the split is possible: zone inside the slab, on grid nodes,
// containing the bullet path up to the slab's far face or to a zone end along it.
#pragma once

#include "core/parameter_problem.h"

#include "coupling/hybrid_parameters.h"
#include "coupling/zone_end.h"
#include "fem/fem_parameters.h"
#include "mpm/scene_parameters.h"

#include <string>
#include <vector>

namespace vulnus::coupling
{
struct HybridScene
{
  mpm::SceneParameters mpm;    ///< the split body clipped to the zone, other bodies unchanged
  fem::FeSceneParameters fe;   ///< the split body minus the zone
  std::size_t coupled_body = 0; ///< index of the split body in mpm.bodies
  std::array<double, 3> initial_velocity{{0.0, 0.0, 0.0}}; ///< of the split body, m/s
  HybridParameters hybrid; ///< with the zone resolved (a zone around the path computed)
  /// Adaptive zone: the box the zone may grow into (the far field's fine region), on grid
  /// nodes; the zone itself otherwise.
  std::array<double, 3> limit_min{{0.0, 0.0, 0.0}};
  std::array<double, 3> limit_max{{0.0, 0.0, 0.0}};
};

/// The hybrid parameters with the zone a deck asks for: its box as given, or the bullet
/// path's tube through the split body (projectile radius plus one cell plus the margin),
/// widened outwards to grid nodes and cut at the body's faces. Unchanged when the body or
/// the projectile cannot be found (check_decomposition then names the problem).
HybridParameters resolve_zone(const mpm::SceneParameters& scene, const HybridParameters& hybrid);

/// Problems with the split (empty when fine), naming HybridParameters' members ("body",
/// "zone_min", "zone_max", "scheme") and the far field's ("far_field.<member>").
std::vector<ParameterProblem> check_decomposition(const mpm::SceneParameters& scene,
                                                  const HybridParameters& hybrid,
                                                  const fem::FeSceneParameters& far_field);

/// Builds the two sub-scenes. far_field supplies the FE numerics (integrator, element degree,
/// mesh grading, tolerances); geometry, material, density, fibers, face conditions and end
/// time come from the scene. Throws std::invalid_argument with all problems of
/// check_decomposition.
HybridScene decompose(const mpm::SceneParameters& scene, const HybridParameters& hybrid,
                      const fem::FeSceneParameters& far_field);

/// Where the deck's zone (resolved) ends along the projectile's flight line inside the split
/// body (`ends` false without a projectile or a body to split).
ZoneEnd zone_end_along_path(const mpm::SceneParameters& scene, const HybridParameters& hybrid);
/// The same for the zone [zone_min, zone_max] of a split scene (the zone now, which an adaptive
/// zone grows).
ZoneEnd zone_end_along_path(const HybridScene& split, const std::array<double, 3>& zone_min,
                            const std::array<double, 3>& zone_max);

/// Index of the body the hybrid splits (hybrid.body or the default choice), or -1.
int split_body_index(const mpm::SceneParameters& scene, const HybridParameters& hybrid);
} // namespace vulnus::coupling
