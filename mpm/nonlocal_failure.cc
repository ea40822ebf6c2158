// Hot cells (a point past a limit by the cheap bound), candidates within the radius of them,
// exact measures within the radius of those, then the means at the candidates over their
// neighbour lists (made once a point first needs a mean, kept while the points stay put).
#include "mpm/nonlocal_failure.h"

#include "materials/material_parameters.h"
#include "materials/two_surface_failure.h"
#include "mpm/nonlocal_average.h"

#include <algorithm>
#include <sstream>
#include <string>

namespace vulnus::mpm
{
namespace
{
const materials::FailureParameters* regularized_criterion(const materials::Material& material)
{
  const materials::FailureParameters* c = material.failure_criterion();
  return c && c->regularization_length > 0.0 ? c : nullptr;
}

/// The body's cached binning and lists, rebuilt when its points changed.
const NonlocalNeighbourhood& neighbourhood_of(NonlocalFailureCache::Body& cached,
                                              const Particles& points, const std::size_t begin,
                                              const std::size_t end, const double radius)
{
  const std::size_t n = end - begin;
  const bool same = cached.neighbourhood && cached.ids.size() == n &&
                    std::equal(cached.ids.begin(), cached.ids.end(), points.id.begin() + begin);
  if (!same)
  {
    cached.ids.assign(points.id.begin() + begin, points.id.begin() + end);
    cached.neighbourhood = std::make_unique<NonlocalNeighbourhood>(points, begin, end, radius);
    cached.lists.assign(n, {});
    cached.listed.assign(n, 0);
  }
  return *cached.neighbourhood;
}

void decide_for_body(const materials::FailureParameters& c, const bool fibers,
                     Particles& points, const std::size_t begin, const std::size_t end,
                     NonlocalFailureCache::Body& cached)
{
  const long n = static_cast<long>(end - begin);
  if (n == 0)
    return;
  const NonlocalNeighbourhood& neighbourhood =
      neighbourhood_of(cached, points, begin, end, c.regularization_length);
  std::vector<double> shear(n), stretch(n, 0.0);
  std::vector<char> counted(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
  {
    const std::size_t p = begin + i;
    counted[i] = (points.failure[p] & materials::total_failure) != materials::total_failure;
    const Tensor2& F = points.deformation_gradient[p];
    shear[i] = materials::matrix_shear_bound(c, F);
    if (fibers)
      stretch[i] = (F * points.fiber_direction[p].cast<double>().normalized()).norm();
  }
  std::vector<char> hot(neighbourhood.n_cells(), 0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    if (counted[i] && (shear[i] > c.matrix_shear_limit ||
                       (fibers && stretch[i] > c.fiber_stretch_limit)))
    {
#pragma omp atomic write
      hot[neighbourhood.cell_of(begin + i)] = 1;
    }
  const std::vector<char> candidate = neighbourhood.grown_by_the_radius(hot);
  // Exact shear measures are needed only around the candidates whose matrix can still fail
  // (a point with failed matrix and intact fibers needs the stretch mean alone).
  std::vector<char> shear_mean_needed(neighbourhood.n_cells(), 0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
  {
    const std::size_t cell = neighbourhood.cell_of(begin + i);
    if (counted[i] && candidate[cell] && !(points.failure[begin + i] & materials::matrix_failed))
    {
#pragma omp atomic write
      shear_mean_needed[cell] = 1;
    }
  }
  const std::vector<char> measured = neighbourhood.grown_by_the_radius(shear_mean_needed);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    if (measured[neighbourhood.cell_of(begin + i)])
      shear[i] = materials::matrix_shear_at(c, points.deformation_gradient[begin + i]);
  const std::vector<double> shear_sorted = neighbourhood.in_cell_order(shear.data());
  const std::vector<double> stretch_sorted = neighbourhood.in_cell_order(stretch.data());
  const std::vector<char> counted_sorted = neighbourhood.in_cell_order(counted.data());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i)
  {
    const std::size_t p = begin + i;
    std::uint8_t byte = (points.failure[p] & materials::total_failure) |
                        materials::failure_decided_outside;
    if (counted[i] && candidate[neighbourhood.cell_of(p)])
    {
      const bool matrix = !(byte & materials::matrix_failed);
      const bool fiber = fibers && !(byte & materials::fiber_failed);
      if ((matrix || fiber) && !cached.listed[i])
      {
        cached.lists[i] = neighbourhood.neighbours(p);
        cached.listed[i] = 1;
      }
      const std::vector<NonlocalNeighbour>& list = cached.lists[i];
      if (matrix && fiber)
      {
        const std::array<double, 2> m = NonlocalNeighbourhood::list_means(
          list, shear_sorted.data(), stretch_sorted.data(), counted_sorted.data());
        if (m[0] > c.matrix_shear_limit)
          byte |= materials::matrix_fails_now;
        if (m[1] > c.fiber_stretch_limit)
          byte |= materials::fibers_fail_now;
      }
      else if (matrix && NonlocalNeighbourhood::list_mean(list, shear_sorted.data(),
                                                          counted_sorted.data()) >
                           c.matrix_shear_limit)
        byte |= materials::matrix_fails_now;
      else if (fiber && NonlocalNeighbourhood::list_mean(list, stretch_sorted.data(),
                                                         counted_sorted.data()) >
                          c.fiber_stretch_limit)
        byte |= materials::fibers_fail_now;
    }
    points.failure[p] = byte;
  }
}
} // namespace

bool uses_nonlocal_failure(const std::vector<const materials::Material*>& body_material)
{
  for (const materials::Material* m : body_material)
    if (regularized_criterion(*m))
      return true;
  return false;
}

void decide_nonlocal_failures(const std::vector<const materials::Material*>& body_material,
                              Particles& points, NonlocalFailureCache& cache)
{
  cache.bodies.resize(points.n_bodies());
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
    if (const materials::FailureParameters* c = regularized_criterion(*body_material[b]))
      decide_for_body(*c, body_material[b]->uses_fibers(), points, points.begin_of(b),
                      points.end_of(b), cache.bodies[b]);
}

std::vector<ParameterProblem> check_regularization(const materials::FailureParameters& failure,
                                                   const double cell_size, const int n_ranks)
{
  std::vector<ParameterProblem> problems;
  const double l = failure.regularization_length;
  if (!failure.enabled || !(l > 0.0))
    return problems;
  if (cell_size > 0.0 && l < 0.5 * cell_size)
  {
    std::ostringstream s;
    s << "l = " << l << " m is below half the cell size " << cell_size
      << " m, so a point's mean would hold hardly more than itself";
    problems.push_back({{"regularization_length"}, s.str(),
                        "give l of a few cell sizes (the failed zone is then about l wide), or "
                        "0 for the local criterion"});
  }
  if (n_ranks > 1)
    problems.push_back({{"regularization_length"},
                        "the nonlocal criterion runs on one MPI rank only (this run has " +
                          std::to_string(n_ranks) + ")",
                        "run on one rank, or set it to 0 for the local criterion"});
  return problems;
}
} // namespace vulnus::mpm
