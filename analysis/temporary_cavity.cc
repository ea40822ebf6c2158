// The temporary cavity: the target's stand-off from the path, by slice and sector, over time.
#include "analysis/temporary_cavity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vulnus::analysis
{
namespace
{
constexpr double pi = 3.14159265358979323846;
}

TemporaryCavity::TemporaryCavity(const mpm::Solver& solver)
{
  const int projectile = solver.projectile();
  const mpm::Particles& points = solver.points();
  if (projectile < 0 || points.n_bodies() < 2)
    return;
  const mpm::SceneParameters& scene = solver.scene();
  axis = solver.flight_direction();
  across_1 = std::abs(axis[0]) < 0.9 ? mpm::Vector3::UnitX() : mpm::Vector3::UnitY();
  across_1 = (across_1 - across_1.dot(axis) * axis).normalized();
  across_2 = axis.cross(across_1);

  double sums[4] = {0.0, 0.0, 0.0, 0.0}; // mass, first moment
  for (std::size_t p = points.begin_of(projectile); p < points.end_of(projectile); ++p)
  {
    sums[0] += points.mass[p];
    for (int d = 0; d < 3; ++d)
      sums[1 + d] += points.mass[p] * points.position[p][d];
  }
  solver.rank_group().sum(sums, 4);
  if (!(sums[0] > 0.0))
    return;
  // Across mirror planes the points are the projectile's modelled part; its whole lies on them.
  const mpm::Vector3 centre =
    mpm::onto_planes(mpm::Vector3(sums[1], sums[2], sums[3]) / sums[0], solver.mirror_planes());
  const auto [entrance, exit] = solver.target_extent_along_flight();
  thickness = scene.cell_size;
  unsigned int ppc = 1;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (static_cast<int>(b) != projectile)
      ppc = std::max(ppc, scene.bodies[b].particles_per_cell);
  half_spacing = 0.5 * scene.cell_size / ppc;
  // Slices start at the entrance point on the target's surface (for a normal shot half a
  // spacing before the first layer of points, so that no layer lies on a slice boundary).
  origin = centre + (entrance - centre.dot(axis)) * axis;
  mpm::Vector3 domain_min = scene.domain_min, domain_max = scene.domain_max;
  mpm::mirror_box(domain_min, domain_max, solver.mirror_planes());
  radius_cap = (domain_max - domain_min).norm();
  const auto n_slices =
      static_cast<std::size_t>(std::ceil((exit - entrance) / thickness - 1e-9));
  slices.resize(std::max<std::size_t>(n_slices, 1));
  for (std::size_t k = 0; k < slices.size(); ++k)
    slices[k].depth = (k + 0.5) * thickness;
  nearest.assign(slices.size() * sectors, radius_cap);
}

std::array<double, TemporaryCavity::sectors>
TemporaryCavity::distances_to_the_box(const mpm::Vector3& lower, const mpm::Vector3& upper) const
{
  std::array<double, sectors> distances;
  for (std::size_t s = 0; s < sectors; ++s)
  {
    const double angle = (s + 0.5) * 2.0 * pi / sectors;
    const mpm::Vector3 direction = std::cos(angle) * across_1 + std::sin(angle) * across_2;
    double distance = radius_cap;
    for (int d = 0; d < 3; ++d)
    {
      if (std::abs(direction[d]) < 1e-12)
        continue;
      const double face = direction[d] > 0.0 ? upper[d] : lower[d];
      distance = std::min(distance, std::max(0.0, (face - origin[d]) / direction[d]));
    }
    distances[s] = distance;
  }
  return distances;
}

void TemporaryCavity::sample(const mpm::Solver& solver)
{
  if (!active())
    return;
  const mpm::Particles& points = solver.points();
  // A point stands for the material within a point spacing of it: it counts in every slice
  // and sector that reach comes into. A wall point that moves across a slice's or a sector's
  // boundary then leaves no empty bin behind it, which would read as a wall jumping outwards.
  const double reach = 2.0 * half_spacing;
  const double sector_angle = 2.0 * pi / sectors;
  const bool ring_points = solver.scene().axisymmetric;
  // Negated distances, so that one element-wise max over the ranks gives the nearest.
  std::fill(nearest.begin(), nearest.end(), -radius_cap);
  constexpr double inf = std::numeric_limits<double>::infinity();
  double extent[6] = {-inf, -inf, -inf, -inf, -inf, -inf}; // the target points' box, negated low
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
  {
    if (static_cast<int>(b) == solver.projectile())
      continue;
    for (std::size_t p = points.begin_of(b); p < points.end_of(b); ++p)
      for (const mpm::Vector3& x : mpm::mirror_images(points.position[p], solver.mirror_planes()))
    {
      for (int d = 0; d < 3; ++d)
      {
        extent[d] = std::max(extent[d], -x[d]);
        extent[3 + d] = std::max(extent[3 + d], x[d]);
      }
      if (points.failure[p] == materials::total_failure)
        continue;
      const mpm::Vector3 offset = x - origin;
      const double along = offset.dot(axis);
      const double first = std::floor((along - reach) / thickness);
      const double last = std::floor((along + reach) / thickness);
      if (last < 0.0 || first >= static_cast<double>(slices.size()))
        continue;
      const double u = offset.dot(across_1), v = offset.dot(across_2);
      const double r = std::sqrt(u * u + v * v);
      double angle = std::atan2(v, u);
      if (angle < 0.0)
        angle += 2.0 * pi;
      // An axisymmetric scene's point is a ring: it stands in every sector.
      const double half_width = r > reach && !ring_points ? std::asin(reach / r) : pi;
      const auto lowest = static_cast<long>(std::floor((angle - half_width) / sector_angle));
      const auto highest = static_cast<long>(std::floor((angle + half_width) / sector_angle));
      constexpr long n_all = sectors;
      const long n_sectors = std::min(n_all, highest - lowest + 1);
      const auto k_end = std::min(slices.size(), static_cast<std::size_t>(last) + 1);
      for (auto k = static_cast<std::size_t>(std::max(0.0, first)); k < k_end; ++k)
        for (long i = 0; i < n_sectors; ++i)
        {
          const long s = ((lowest + i) % n_all + n_all) % n_all;
          double& slot = nearest[k * sectors + static_cast<std::size_t>(s)];
          slot = std::max(slot, -r);
        }
    }
  }
  solver.rank_group().max(nearest.data(), static_cast<int>(nearest.size()));
  solver.rank_group().max(extent, 6);
  const double time = solver.time();
  const bool first = floor_diameter < 0.0;
  // Beyond a hybrid's MPM points lies the far field's material: no wall is farther than them.
  mpm::Vector3 domain_min = solver.scene().domain_min, domain_max = solver.scene().domain_max;
  mpm::mirror_box(domain_min, domain_max, solver.mirror_planes());
  std::array<double, sectors> edge = distances_to_the_box(domain_min, domain_max);
  if (ring_points) // the grid's edge is the radius of its plane
    edge.fill(solver.scene().domain_max[0]);
  if (!solver.scene().deck_bodies.empty())
  {
    const mpm::Vector3 low = mpm::Vector3(-extent[0], -extent[1], -extent[2]).array() - half_spacing;
    const mpm::Vector3 high = mpm::Vector3(extent[3], extent[4], extent[5]).array() + half_spacing;
    const std::array<double, sectors> zone = distances_to_the_box(low, high);
    for (std::size_t s = 0; s < sectors; ++s)
      edge[s] = std::min(edge[s], zone[s]);
  }
  for (std::size_t k = 0; k < slices.size(); ++k)
  {
    double area = 0.0;
    Slice& slice = slices[k];
    for (std::size_t s = 0; s < sectors; ++s)
    {
      if (first && -nearest[k * sectors + s] >= radius_cap)
        slice.inside_target = false;
      const double wall =
          std::min(edge[s], std::max(0.0, -nearest[k * sectors + s] - half_spacing));
      area += pi * wall * wall / sectors;
    }
    slice.diameter = std::sqrt(4.0 * area / pi);
    if (first && slice.inside_target)
      floor_diameter = std::max(floor_diameter, slice.diameter);
    if (slice.diameter > slice.max_diameter)
    {
      slice.max_diameter = slice.diameter;
      slice.max_time = time;
    }
  }
}

const TemporaryCavity::Slice& TemporaryCavity::largest() const
{
  static const Slice none;
  if (slices.empty())
    return none;
  const Slice* peak = &none;
  for (const Slice& s : slices)
    if (s.inside_target && s.max_diameter > peak->max_diameter)
      peak = &s;
  return *peak;
}

std::vector<double> TemporaryCavity::packed() const
{
  std::vector<double> values = {origin[0],   origin[1],   origin[2],   axis[0],     axis[1],
                                axis[2],     across_1[0], across_1[1], across_1[2], across_2[0],
                                across_2[1], across_2[2], thickness,   half_spacing, radius_cap,
                                floor_diameter};
  for (const Slice& s : slices)
    values.insert(values.end(),
                  {s.depth, s.diameter, s.max_diameter, s.max_time, double(s.inside_target)});
  return values;
}

void TemporaryCavity::unpack(const std::vector<double>& values)
{
  constexpr std::size_t head = 16;
  if (values.size() < head || (values.size() - head) % 5 != 0)
    throw std::runtime_error("checkpoint: the temporary cavity's record is malformed");
  origin = {values[0], values[1], values[2]};
  axis = {values[3], values[4], values[5]};
  across_1 = {values[6], values[7], values[8]};
  across_2 = {values[9], values[10], values[11]};
  thickness = values[12];
  half_spacing = values[13];
  radius_cap = values[14];
  floor_diameter = values[15];
  slices.clear();
  for (std::size_t i = head; i < values.size(); i += 5)
    slices.push_back({values[i], values[i + 1], values[i + 2], values[i + 3], values[i + 4] != 0.0});
  nearest.assign(slices.size() * sectors, radius_cap);
}
} // namespace vulnus::analysis
