// Point generation for the bodies of a scene.
#include "mpm/body_builder.h"

#include "materials/fiber_field.h"
#include "mpm/axisymmetry.h"
#include "mpm/symmetry_planes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace vulnus::mpm
{
bool body_contains(const BodyParameters& body, const Vector3& x)
{
  switch (body.shape)
  {
    case BodyShape::box:
      return (x.array() >= body.box_min.array()).all() && (x.array() <= body.box_max.array()).all();
    case BodyShape::sphere:
      return (x - body.center).squaredNorm() <= body.radius * body.radius;
    case BodyShape::cylinder:
    {
      const Vector3 axis = body.axis.normalized();
      const Vector3 d = x - body.center;
      const double along = d.dot(axis);
      const double radial2 = (d - along * axis).squaredNorm();
      if (along < 0.0 || along > body.length)
        return false;
      const double r2 = body.radius * body.radius;
      if (body.nose == NoseShape::flat)
        return radial2 <= r2;
      const double shank = body.length - body.radius;
      if (along <= shank)
        return radial2 <= r2;
      const double ahead = along - shank;
      return radial2 + ahead * ahead <= r2;
    }
  }
  return false;
}

double body_volume(const BodyParameters& body)
{
  switch (body.shape)
  {
    case BodyShape::box:
      return (body.box_max - body.box_min).prod();
    case BodyShape::sphere:
      return 4.0 / 3.0 * M_PI * std::pow(body.radius, 3);
    case BodyShape::cylinder:
    {
      const double r2 = body.radius * body.radius;
      if (body.nose == NoseShape::flat)
        return M_PI * r2 * body.length;
      return M_PI * r2 * (body.length - body.radius) + 2.0 / 3.0 * M_PI * r2 * body.radius;
    }
  }
  return 0.0;
}

void body_bounding_box(const BodyParameters& body, Vector3& lower, Vector3& upper)
{
  switch (body.shape)
  {
    case BodyShape::box:
      lower = body.box_min;
      upper = body.box_max;
      return;
    case BodyShape::sphere:
      lower = body.center.array() - body.radius;
      upper = body.center.array() + body.radius;
      return;
    case BodyShape::cylinder:
    {
      const Vector3 axis = body.axis.normalized();
      const Vector3 tip = body.center + body.length * axis;
      for (int d = 0; d < 3; ++d)
      {
        const double extent = body.radius * std::sqrt(std::max(0.0, 1.0 - axis[d] * axis[d]));
        lower[d] = std::min(body.center[d], tip[d]) - extent;
        upper[d] = std::max(body.center[d], tip[d]) + extent;
      }
      return;
    }
  }
}

double gap_to_domain_face(const SceneParameters& scene, const BodyParameters& body, const int face)
{
  Vector3 lower, upper;
  body_bounding_box(body, lower, upper);
  const int d = face / 2;
  return face % 2 == 0 ? lower[d] - scene.domain_min[d] : scene.domain_max[d] - upper[d];
}

namespace
{
/// The lattice of one axis over [lower, upper]: n points per cell at sub-cell centres, each
/// with its spacing (the cell's width / n).
struct AxisLattice
{
  std::vector<double> position, spacing;
};

AxisLattice axis_lattice(const Grid& grid, const int axis, const double lower, const double upper,
                         const unsigned int n)
{
  AxisLattice lattice;
  const double origin = grid.origin()[axis];
  if (!grid.graded())
  {
    const double spacing = grid.cell_size() / n;
    const long first = static_cast<long>(std::floor((lower - origin) / spacing));
    const long last = static_cast<long>(std::ceil((upper - origin) / spacing));
    for (long i = first; i <= last; ++i)
    {
      lattice.position.push_back(origin + spacing * (i + 0.5));
      lattice.spacing.push_back(spacing);
    }
    return lattice;
  }
  const auto cell_of = [&](const double x)
  {
    const int c = static_cast<int>(std::floor(grid.to_cell_units(Vector3::Constant(x))[axis]));
    return std::clamp(c, -Grid::padding, grid.cells()[axis] + Grid::padding - 1);
  };
  const int first = cell_of(lower), last = cell_of(upper);
  // A cell the body's box cuts gets its n points over the part inside the box, so that a face
  // of the body along the grid's axes (a block's, or a cylinder's ends and, in axisymmetry, its
  // radius) is where the body ends, even in a wide cell.
  for (int c = first; c <= last; ++c)
  {
    const double start = std::max(lower, grid.node_coordinate(axis, c));
    const double end = std::min(upper, grid.node_coordinate(axis, c + 1));
    if (!(end - start > 1e-9 * grid.cell_size()))
      continue;
    const double spacing = (end - start) / n;
    for (unsigned int a = 0; a < n; ++a)
    {
      lattice.position.push_back(start + spacing * (a + 0.5));
      lattice.spacing.push_back(spacing);
    }
  }
  return lattice;
}

/// Calls f(x, volume) for each lattice point of `body` (n per cell and axis, at sub-cell
/// centres) on the domain's side of the mirror planes. On an axisymmetric grid the lattice is
/// the r-y plane's (z = 0, r > 0) and each point the ring it sweeps about the axis.
template <class F>
void for_each_point_of(const BodyParameters& body, const Grid& grid,
                       const std::vector<SymmetryPlane>& planes, F&& f)
{
  Vector3 lower = Vector3::Zero(), upper = Vector3::Zero();
  body_bounding_box(body, lower, upper);
  for (const SymmetryPlane& plane : planes)
  {
    double& bound = plane.face % 2 == 0 ? lower[plane.axis] : upper[plane.axis];
    bound = plane.face % 2 == 0 ? std::max(bound, plane.coordinate)
                                : std::min(bound, plane.coordinate);
  }
  std::array<AxisLattice, 3> axis;
  for (int d = 0; d < 3; ++d)
    axis[d] = axis_lattice(grid, d, lower[d], upper[d], body.particles_per_cell);
  if (grid.axisymmetric())
  {
    std::size_t first_r = 0;
    while (first_r < axis[0].position.size() && axis[0].position[first_r] < 0.0)
      ++first_r;
    axis[0].position.erase(axis[0].position.begin(), axis[0].position.begin() + first_r);
    axis[0].spacing.erase(axis[0].spacing.begin(), axis[0].spacing.begin() + first_r);
    axis[2].position.assign(1, 0.0);
    axis[2].spacing.assign(1, grid.cell_size() / body.particles_per_cell);
  }
  for (std::size_t k = 0; k < axis[2].position.size(); ++k)
    for (std::size_t j = 0; j < axis[1].position.size(); ++j)
      for (std::size_t i = 0; i < axis[0].position.size(); ++i)
      {
        const Vector3 x(axis[0].position[i], axis[1].position[j], axis[2].position[k]);
        if (!body_contains(body, x))
          continue;
        const double area = axis[0].spacing[i] * axis[1].spacing[j];
        f(x, grid.axisymmetric() ? ring_volume(x[0], area) : area * axis[2].spacing[k]);
      }
}
} // namespace

void visit_body_points(const SceneParameters& scene, const Grid& grid,
                       const std::function<void(const Vector3&)>& visit)
{
  const std::vector<SymmetryPlane> planes = symmetry_planes(scene);
  for (const BodyParameters& body : scene.bodies)
    for_each_point_of(body, grid, planes, [&](const Vector3& x, double) { visit(x); });
}

void build_bodies(const SceneParameters& scene, const Grid& grid, Particles& particles,
                  const std::vector<char>& plastic_history,
                  const std::function<bool(const Vector3&)>& keep)
{
  auto plastic = [&plastic_history](std::size_t b)
  { return b < plastic_history.size() && plastic_history[b]; };
  // Counted first so that every array is allocated once (growing them by doubling would
  // leave the old copies in the resident set).
  std::size_t n_stored = particles.size(), n_plastic = particles.plastic_pool.size();
  const std::vector<SymmetryPlane> planes = symmetry_planes(scene);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    for_each_point_of(scene.bodies[b], grid, planes, [&](const Vector3& x, double) {
      const bool stored = !keep || keep(x);
      n_stored += stored;
      n_plastic += stored && plastic(b);
    });
  particles.reserve(n_stored, n_plastic);
  std::uint32_t next_id = 0;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
  {
    const BodyParameters& body = scene.bodies[b];
    particles.start_body();
    const std::uint32_t first_id = next_id;
    for_each_point_of(body, grid, planes, [&](const Vector3& x, const double volume) {
      const std::uint32_t id = next_id++;
      if (keep && !keep(x))
        return;
      particles.append(x, body.initial_velocity, body.density * volume, volume,
                       materials::fiber_direction(body.fibers, x), plastic(b));
      particles.id.back() = id;
    });
    particles.finish_body();
    if (next_id == first_id)
      throw std::invalid_argument("Body " + body.name +
                                  ": contains no material point; make it larger than a "
                                  "point spacing (cell size / particles per cell)");
  }
}
} // namespace vulnus::mpm
