// Point splitting along a point's longest stretched domain edge.
#include "mpm/point_splitting.h"

namespace vulnus::mpm
{
namespace
{
/// The column of the point's domain with the longest edge, or -1 when none exceeds the limit.
int edge_to_split(const Eigen::Matrix3f& domain, const double longest_edge)
{
  int longest = -1;
  double length = longest_edge;
  for (int k = 0; k < 3; ++k)
  {
    const double edge = 2.0 * domain.col(k).cast<double>().norm();
    if (edge > length)
    {
      length = edge;
      longest = k;
    }
  }
  return longest;
}

bool inside(const PointSplitting& s, const Vector3& x)
{
  if ((x.array() < s.lower.array()).any() || (x.array() > s.upper.array()).any())
    return false;
  for (const SymmetryPlane& plane : s.planes)
  {
    const bool lower_face = plane.face % 2 == 0;
    if (lower_face ? x[plane.axis] < plane.coordinate : x[plane.axis] > plane.coordinate)
      return false;
  }
  return !(s.inside_rigid && s.inside_rigid(x));
}
} // namespace

Particles split_stretched_points(Particles& particles, const std::size_t begin,
                                 const std::size_t end, const PointSplitting& settings)
{
  std::vector<std::size_t> parents;
  std::vector<int> edges;
  if (settings.longest_edge > 0.0)
    for (std::size_t p = begin; p < end; ++p)
    {
      if (particles.failure[p] == materials::total_failure)
        continue;
      const int k = edge_to_split(particles.domain[p], settings.longest_edge);
      if (k < 0)
        continue;
      const Vector3 quarter = 0.5 * particles.domain[p].col(k).cast<double>();
      if (!inside(settings, particles.position[p] + quarter) ||
          !inside(settings, particles.position[p] - quarter))
        continue;
      parents.push_back(p);
      edges.push_back(k);
    }

  Particles children;
  children.for_each_array_with(particles, [&](auto& mine, const auto& theirs)
                               {
                                 mine.reserve(parents.size());
                                 for (const std::size_t p : parents)
                                   mine.push_back(theirs[p]);
                               });
  children.body_begin = {0, parents.size()};
  for (std::size_t i = 0; i < parents.size(); ++i)
  {
    const std::size_t p = parents[i];
    const int k = edges[i];
    particles.domain[p].col(k) *= 0.5f;
    const Vector3 quarter = particles.domain[p].col(k).cast<double>();
    particles.position[p] += quarter;
    particles.mass[p] *= 0.5;
    particles.reference_volume[p] *= 0.5;
    children.position[i] = particles.position[p] - 2.0 * quarter;
    children.domain[i] = particles.domain[p];
    children.mass[i] = particles.mass[p];
    children.reference_volume[i] = particles.reference_volume[p];
    if (const materials::PlasticHistory* history = particles.plastic_of(p))
    {
      children.plastic_slot[i].index = static_cast<std::uint32_t>(children.plastic_pool.size());
      children.plastic_pool.push_back(*history);
    }
  }
  return children;
}
} // namespace vulnus::mpm
