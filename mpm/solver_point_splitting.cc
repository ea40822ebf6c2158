// The solver's side of point splitting (mpm/point_splitting.h): which bodies split, where the
// children may go, and their ids.
#include "mpm/solver.h"

#include "mpm/shape_distance.h"

namespace vulnus::mpm
{
void Solver::plan_point_splitting()
{
  const SceneParameters& scene = parameters;
  if (scene.point_split_edge_cells > 0.0 &&
      (scene.axisymmetric || scene.shape_function != ShapeFunction::linear))
    throw std::invalid_argument("Grid/Point splitting takes a 3D grid and linear shape functions "
                                "(a ring, or a GIMP or CPDI domain, does not halve along an edge)");
  splitting.longest_edge = scene.point_split_edge_cells * scene.cell_size;
  splitting.lower = grid.origin();
  splitting.upper = grid.upper_corner();
  splitting.planes = planes_of_symmetry;
}

void Solver::split_stretched_points()
{
  // Set here, not once: the solver may have moved since it was built.
  splitting.inside_rigid = [this](const Vector3& x)
  {
    for (std::size_t r = 0; r < grid_settings.exact_surface.size(); ++r)
      if (grid_settings.exact_surface[r] && grid_settings.body_is_rigid[r] &&
          distance_to_shape(*grid_settings.exact_surface[r], grid_settings.rigid_offset[r], x)
              .distance < 0.0)
        return true;
    return false;
  };
  std::uint64_t made = 0;
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    if (grid_settings.body_is_rigid[b] || static_cast<int>(b) == projectile_body)
      continue;
    Particles children =
      mpm::split_stretched_points(particles, particles.begin_of(b), particles.end_of(b), splitting);
    std::uint64_t count = children.size();
    ranks.sum(&count, 1);
    if (count == 0)
      continue;
    assign_fresh_ids(children);
    made += count;
    particles.insert_into_body(b, children);
  }
  n_split += made;
}
} // namespace vulnus::mpm
