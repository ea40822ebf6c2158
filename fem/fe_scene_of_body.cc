// The FE scene of a box body of a scene description.
#include "fem/fe_scene_of_body.h"

#include <cmath>

namespace vulnus::fem
{
namespace
{
FaceParameters::Condition fe_condition(const scene::FaceCondition support)
{
  switch (support)
  {
  case scene::FaceCondition::fixed:
    return FaceParameters::Condition::fixed;
  case scene::FaceCondition::roller:
  case scene::FaceCondition::symmetry:
    return FaceParameters::Condition::roller;
  case scene::FaceCondition::free:
    break;
  }
  return FaceParameters::Condition::free;
}
} // namespace

FeSceneParameters fe_scene_of_body(const scene::SceneDescription& scene, const std::size_t b,
                                   const FeSceneParameters& numerics)
{
  const scene::BodyParameters& body = scene.bodies.at(b);
  FeSceneParameters fe = numerics;
  for (int d = 0; d < 3; ++d)
  {
    fe.slab_min[d] = body.box_min[d];
    fe.slab_max[d] = body.box_max[d];
  }
  fe.has_hole = false;
  fe.interface_cell_size = scene.cell_size;
  if (const scene::NamedMaterial* material = scene::find_material(scene, body.material))
    fe.material = material->parameters;
  fe.density = body.density;
  fe.fibers = body.fibers;
  fe.end_time = scene.end_time;
  for (unsigned int f = 0; f < n_slab_faces; ++f)
  {
    const FaceParameters::Condition given = numerics.faces[f].condition;
    if (given == FaceParameters::Condition::velocity ||
        given == FaceParameters::Condition::traction)
      continue;
    const int d = f / 2;
    const bool upper = f % 2;
    const double body_face = upper ? body.box_max[d] : body.box_min[d];
    const double box_face = upper ? scene.domain_max[d] : scene.domain_min[d];
    FaceParameters face;
    if (std::abs(body_face - box_face) <= 1e-6 * scene.cell_size)
      face.condition = fe_condition(scene.domain_faces[f]);
    fe.faces[f] = face;
  }
  return fe;
}
} // namespace vulnus::fem
