// The r-y half plane an axisymmetric deck is solved in.
#include "mpm/axisymmetry.h"

namespace vulnus::mpm
{
SceneParameters plane_of_revolution(const SceneParameters& deck)
{
  SceneParameters plane = deck;
  const double half = 0.5 * deck.cell_size;
  plane.domain_min = Vector3(0.0, deck.domain_min[1], -half);
  plane.domain_max = Vector3(deck.domain_max[0], deck.domain_max[1], half);
  plane.grading.fine_min[0] = 0.0; // the fine box's -R_f..R_f is its radius 0..R_f
  plane.domain_faces[0] = FaceCondition::roller; // the axis: v_r = 0
  plane.domain_faces[4] = FaceCondition::roller; // no velocity along the hoop direction
  plane.domain_faces[5] = FaceCondition::roller;
  return plane;
}

void revolve(SceneDiagnostics& d)
{
  d.momentum = revolved(d.momentum);
  for (BodySummary& body : d.bodies)
  {
    body.centroid = revolved(body.centroid);
    body.velocity = revolved(body.velocity);
  }
}
} // namespace vulnus::mpm
