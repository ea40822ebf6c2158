// Where the projectile's path enters and leaves the target: the deck's surfaces along the line
// through the projectile's mass centre, so that depth and cavity start at the entrance point
// whatever the angle of the shot, and the projectile's front from its own shape.
#include "mpm/solver.h"
#include "mpm/target_path.h"

#include <algorithm>
#include <limits>

namespace vulnus::mpm
{
void Solver::measure_path_through_target(const SceneParameters& scene)
{
  const std::vector<BodyParameters>& bodies = scene.deck_bodies.empty() ? scene.bodies : scene.deck_bodies;
  double sums[4] = {0.0, 0.0, 0.0, 0.0}; // mass, first moment
  double foremost = -std::numeric_limits<double>::max();
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
  {
    sums[0] += particles.mass[p];
    for (int d = 0; d < 3; ++d)
      sums[1 + d] += particles.mass[p] * particles.position[p][d];
    foremost = std::max(foremost, particles.position[p].dot(flight_axis));
  }
  ranks.sum(sums, 4);
  foremost = ranks.max(foremost);
  const Vector3 origin = sums[0] > 0.0 ? Vector3(Vector3(sums[1], sums[2], sums[3]) / sums[0])
                                       : scene.bodies[projectile_body].center;
  nose_offset = std::max(0.0, reach_along(bodies[projectile_body], flight_axis) - foremost);

  // Shapes without a closed form here: their points within a cell of the path, each reaching
  // half its spacing beyond itself. Entrances are kept negated, so that one max reduces all.
  constexpr double none = -std::numeric_limits<double>::max();
  double planes[4] = {none, none, none, none}; // -entrance, exit on the path; over all points
  const auto keep = [&planes](const int k, const double value) { planes[k] = std::max(planes[k], value); };
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    if (static_cast<int>(b) == projectile_body)
      continue;
    const PathSpan span = path_through_body(bodies[b], origin, flight_axis);
    if (span.hits)
    {
      keep(0, -(origin.dot(flight_axis) + span.t_in));
      keep(1, origin.dot(flight_axis) + span.t_out);
    }
    const double half_spacing = 0.5 * scene.cell_size / scene.bodies[b].particles_per_cell;
    for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
    {
      const Vector3 offset = particles.position[p] - origin;
      const double along = particles.position[p].dot(flight_axis);
      keep(2, -along);
      keep(3, along);
      if (!span.shape_known &&
          (offset - offset.dot(flight_axis) * flight_axis).norm() < scene.cell_size)
      {
        keep(0, -(along - half_spacing));
        keep(1, along + half_spacing);
      }
    }
  }
  ranks.max(planes, 4);
  path_hits_target = planes[0] > none;
  entrance_plane = path_hits_target ? -planes[0] : -planes[2];
  exit_plane = path_hits_target ? planes[1] : planes[3];
}
} // namespace vulnus::mpm
