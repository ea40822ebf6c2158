// The FE scene of one box body of a scene description: its geometry, material, density,
// fibers and supports, with the numerics (integrator, mesh grading, tolerances, loads) given.
// A pure-FE run meshes its body this way; the hybrid meshes the split body's far field so.
#pragma once

#include "fem/fem_parameters.h"
#include "scene/scene_description.h"

#include <cstddef>

namespace vulnus::fem
{
/// The FE description of box body `body` alone (no hole): geometry, material, density, fibers
/// and end time from the scene; a face on the scene's box takes that face's support, a face
/// loaded in `numerics` (velocity or traction) keeps its load, others are free. The cells next
/// to a hole (or the finest ones) take the scene's cell size.
FeSceneParameters fe_scene_of_body(const scene::SceneDescription& scene, std::size_t body,
                                   const FeSceneParameters& numerics);
} // namespace vulnus::fem
