// Size of an MPM scene before it is built: grid nodes, material points and memory, so a deck
// too large for the machine is refused before any work and callers can skip huge scenes.
#pragma once

#include "mpm/scene_parameters.h"

namespace vulnus::deck
{
struct SceneSize
{
  double box_nodes = 0.0; ///< nodes of the grid box, including the padding layers
  double points = 0.0;    ///< upper bound: bounding boxes of the bodies (clipped to the grid)
  double bytes = 0.0;     ///< resident memory estimate of a run
};

/// Bytes of resident memory per material point in a run at the paper's resolution, grid and
/// output buffers included (peak resident set / points, benchmarks/throughput), rounded up.
inline constexpr double resident_bytes_per_point = 1000.0;

/// Estimate for valid geometry (cell size > 0, ordered corners); doubles avoid overflow.
SceneSize estimate_scene_size(const mpm::SceneParameters& scene);

/// Physical memory of this machine in bytes (0 when unknown).
double physical_memory_bytes();
} // namespace vulnus::deck
