// Size of an MPM scene before it is built.
#include "deck/scene_size.h"

#include "mpm/axisymmetry.h"
#include "mpm/body_builder.h"
#include "mpm/grid.h"

#include <unistd.h>

#include <cmath>

namespace vulnus::deck
{
SceneSize estimate_scene_size(const mpm::SceneParameters& deck)
{
  // An axisymmetric scene is its r-y plane, one cell thick.
  const mpm::SceneParameters scene = deck.axisymmetric ? mpm::plane_of_revolution(deck) : deck;
  SceneSize size;
  const double h = scene.cell_size;
  size.box_nodes = 1.0;
  for (int d = 0; d < 3; ++d)
    size.box_nodes *= std::ceil((scene.domain_max[d] - scene.domain_min[d]) / h) + 1.0 +
                      2.0 * mpm::Grid::padding;
  for (const mpm::BodyParameters& body : scene.bodies)
  {
    mpm::Vector3 lower, upper;
    mpm::body_bounding_box(body, lower, upper);
    const mpm::Vector3 extent =
      (upper.cwiseMin(scene.domain_max) - lower.cwiseMax(scene.domain_min)).cwiseMax(0.0);
    const double per_axis = body.particles_per_cell;
    if (scene.axisymmetric)
      size.points += extent[0] * extent[1] / (h * h) * per_axis * per_axis;
    else
      size.points += extent.prod() / (h * h * h) * per_axis * per_axis * per_axis;
  }
  size.bytes = size.points * resident_bytes_per_point + size.box_nodes * sizeof(std::int32_t);
  return size;
}

double physical_memory_bytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page_size > 0 ? double(pages) * double(page_size) : 0.0;
}
} // namespace vulnus::deck
