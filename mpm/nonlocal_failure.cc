// Hot cells per phase (a point past that phase's limit, the shear by its cheap bound),
// candidates within the radius of them, exact shear measures within the radius of the shear
// candidates, then the means at the candidates whose last mean may have moved past the limit
// (mpm/nonlocal_drift.h), over their neighbour lists (made when a point comes to need a mean,
// kept while it does and the points stay put, up to a memory budget).
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
    cached.listed_entries = 0;
    cached.shear_drift.reset(*cached.neighbourhood, n);
    cached.stretch_drift.reset(*cached.neighbourhood, n);
  }
  return *cached.neighbourhood;
}

void decide_for_body(const materials::FailureParameters& c, const bool fibers,
                     Particles& points, const std::size_t begin, const std::size_t end,
                     NonlocalFailureCache::Body& cached, const std::size_t max_listed_entries,
                     const std::uint8_t* passed)
{
  const long n = static_cast<long>(end - begin);
  if (n == 0)
    return;
  const NonlocalNeighbourhood& neighbourhood =
      neighbourhood_of(cached, points, begin, end, c.regularization_length);
  // A weighted mean passes a limit only where some value within the radius does, so each
  // phase's means are needed only within the radius of the cells holding a point past its
  // limit (the shear by its bound), and only at points whose phase is still intact.
  std::vector<char> counted(n);
  std::vector<char> hot_shear(neighbourhood.n_cells(), 0), hot_stretch(neighbourhood.n_cells(), 0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
  {
    const std::size_t p = begin + i;
    counted[i] = (points.failure[p] & materials::total_failure) != materials::total_failure;
    if (!counted[i])
      continue;
    const std::uint8_t past =
      passed ? passed[i]
             : limits_passed(c, fibers, points.deformation_gradient[p], points.fiber_direction[p]);
    if (past & shear_past_limit)
    {
#pragma omp atomic write
      hot_shear[neighbourhood.cell_of(p)] = 1;
    }
    if (past & stretch_past_limit)
    {
#pragma omp atomic write
      hot_stretch[neighbourhood.cell_of(p)] = 1;
    }
  }
  const std::vector<char> shear_candidate = neighbourhood.grown_by_the_radius(hot_shear);
  const std::vector<char> stretch_candidate =
    fibers ? neighbourhood.grown_by_the_radius(hot_stretch) : hot_stretch;
  auto needs_shear_mean = [&](const long i) {
    return counted[i] && shear_candidate[neighbourhood.cell_of(begin + i)] &&
           !(points.failure[begin + i] & materials::matrix_failed);
  };
  auto needs_stretch_mean = [&](const long i) {
    return fibers && counted[i] && stretch_candidate[neighbourhood.cell_of(begin + i)] &&
           !(points.failure[begin + i] & materials::fiber_failed);
  };
  // Exact shear measures (eigenvalues) are needed only within the radius of the points that
  // need a shear mean, and changes of the stretch within the radius of those needing its mean.
  const long cells = static_cast<long>(neighbourhood.n_cells());
  std::vector<char> shear_mean_needed(cells, 0), stretch_mean_needed(cells, 0);
#pragma omp parallel for schedule(dynamic, 64)
  for (long cell = 0; cell < cells; ++cell)
    if (shear_candidate[cell] || stretch_candidate[cell])
      for (std::size_t s = neighbourhood.cell_begin(cell); s < neighbourhood.cell_end(cell); ++s)
      {
        const long i = static_cast<long>(neighbourhood.binned_at(s));
        shear_mean_needed[cell] |= needs_shear_mean(i);
        stretch_mean_needed[cell] |= needs_stretch_mean(i);
      }
  const std::vector<char> measured = neighbourhood.grown_by_the_radius(shear_mean_needed);
  const std::vector<char> stretched =
    fibers ? neighbourhood.grown_by_the_radius(stretch_mean_needed) : stretch_mean_needed;
  std::vector<double> shear(n, 0.0), stretch(n, 0.0);
#pragma omp parallel for schedule(dynamic, 2048)
  for (long i = 0; i < n; ++i)
  {
    const std::size_t cell = neighbourhood.cell_of(begin + i);
    const Tensor2& F = points.deformation_gradient[begin + i];
    if (measured[cell])
      shear[i] = materials::matrix_shear_at(c, F);
    if (stretched[cell])
      stretch[i] = fiber_stretch(F, points.fiber_direction[begin + i]);
  }
  cached.shear_drift.advance(neighbourhood, shear.data(), counted.data(), measured);
  if (fibers)
    cached.stretch_drift.advance(neighbourhood, stretch.data(), counted.data(), stretched);
  const std::vector<double> shear_sorted = neighbourhood.in_cell_order(shear.data());
  const std::vector<double> stretch_sorted = neighbourhood.in_cell_order(stretch.data());
  const std::vector<char> counted_sorted = neighbourhood.in_cell_order(counted.data());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i)
  {
    const std::size_t p = begin + i;
    std::uint8_t byte = (points.failure[p] & materials::total_failure) |
                        materials::failure_decided_outside;
    const std::size_t cell = neighbourhood.cell_of(p);
    const bool shear_needed = needs_shear_mean(i), stretch_needed = needs_stretch_mean(i);
    if (!shear_needed && !stretch_needed && cached.listed[i])
    {
      // A point that needs no mean now gives its list back (it may need it again later).
#pragma omp atomic update
      cached.listed_entries -= cached.lists[i].size();
      std::vector<NonlocalNeighbour>().swap(cached.lists[i]);
      cached.listed[i] = 0;
    }
    const bool matrix =
      shear_needed && cached.shear_drift.may_pass(i, cell, c.matrix_shear_limit);
    const bool fiber =
      stretch_needed && cached.stretch_drift.may_pass(i, cell, c.fiber_stretch_limit);
    if (matrix || fiber)
    {
#pragma omp atomic update
      cached.means_taken += matrix + fiber;
      std::vector<NonlocalNeighbour> unkept;
      if (!cached.listed[i])
      {
        unkept = neighbourhood.neighbours(p);
        std::size_t entries = 0;
#pragma omp atomic capture
        entries = cached.listed_entries += unkept.size();
        if (entries <= max_listed_entries)
        {
          cached.lists[i] = std::move(unkept);
          cached.listed[i] = 1;
        }
        else
        {
#pragma omp atomic update
          cached.listed_entries -= unkept.size();
        }
      }
      const std::vector<NonlocalNeighbour>& list = cached.listed[i] ? cached.lists[i] : unkept;
      double shear_mean = 0.0, stretch_mean = 0.0;
      if (matrix && fiber)
      {
        const std::array<double, 2> m = NonlocalNeighbourhood::list_means(
          list, shear_sorted.data(), stretch_sorted.data(), counted_sorted.data());
        shear_mean = m[0];
        stretch_mean = m[1];
      }
      else if (matrix)
        shear_mean = NonlocalNeighbourhood::list_mean(list, shear_sorted.data(),
                                                      counted_sorted.data());
      else
        stretch_mean = NonlocalNeighbourhood::list_mean(list, stretch_sorted.data(),
                                                        counted_sorted.data());
      if (matrix)
      {
        cached.shear_drift.computed(i, cell, shear_mean, c.matrix_shear_limit);
        if (shear_mean > c.matrix_shear_limit)
          byte |= materials::matrix_fails_now;
      }
      if (fiber)
      {
        cached.stretch_drift.computed(i, cell, stretch_mean, c.fiber_stretch_limit);
        if (stretch_mean > c.fiber_stretch_limit)
          byte |= materials::fibers_fail_now;
      }
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
                              Particles& points, NonlocalFailureCache& cache,
                              FailureLimitFlags* limit_flags)
{
  cache.bodies.resize(points.n_bodies());
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
    if (const materials::FailureParameters* c = regularized_criterion(*body_material[b]))
    {
      const std::size_t begin = points.begin_of(b);
      const bool flagged = limit_flags && limit_flags->filled.size() > b &&
                           limit_flags->filled[b] && limit_flags->passed.size() == points.size();
      decide_for_body(*c, body_material[b]->uses_fibers(), points, begin, points.end_of(b),
                      cache.bodies[b], cache.max_listed_entries,
                      flagged ? limit_flags->passed.data() + begin : nullptr);
      if (flagged)
        limit_flags->filled[b] = 0;
    }
}

FailureLimitFlags failure_limit_flags_for(const std::vector<const materials::Material*>& body_material)
{
  FailureLimitFlags flags;
  for (const materials::Material* m : body_material)
  {
    flags.criterion.push_back(regularized_criterion(*m));
    flags.fibers.push_back(m->uses_fibers());
  }
  flags.filled.assign(body_material.size(), 0);
  return flags;
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
