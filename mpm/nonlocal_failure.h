// The nonlocal failure criterion of the tissue (Failure/Regularization length l > 0): each
// point's matrix shear measure and fiber stretch are averaged over the points within l in
// the reference configuration (mpm/nonlocal_average.h) before they are compared with the
// limits, so a failed zone cannot be narrower than about l whatever the cell size. Only
// points near a point whose measure passes a limit can fail, so the means (and the
// eigenvalues of the shear measure) are computed there alone.
#pragma once

#include "core/parameter_problem.h"
#include "materials/material.h"
#include "mpm/failure_limit_flags.h"
#include "mpm/nonlocal_average.h"
#include "mpm/nonlocal_drift.h"
#include "mpm/particles.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace vulnus::mpm
{
/// What the criterion keeps between steps, per body: the binning of its points by reference
/// position, the neighbour list of every point that needs a mean, and how far each point's
/// last means may have moved since (mpm/nonlocal_drift.h). Reference positions
/// do not move, so both hold while the body's points stay the same in the same order (the
/// points' ids are compared at every step; a re-sort or a removal rebuilds them).
struct NonlocalFailureCache
{
  struct Body
  {
    std::vector<std::uint32_t> ids;
    std::unique_ptr<NonlocalNeighbourhood> neighbourhood;
    std::vector<std::vector<NonlocalNeighbour>> lists; ///< by point (index - begin)
    std::vector<char> listed;
    std::size_t listed_entries = 0;
    std::size_t means_taken = 0; ///< means computed, added up over calls
    NonlocalMeanDrift shear_drift, stretch_drift;
  };
  std::vector<Body> bodies;
  /// Neighbours kept over all lists of a body (8 bytes each: 256 MiB). Lists of points that
  /// need no mean are given back; beyond this, means are taken from lists made on the spot.
  std::size_t max_listed_entries = std::size_t(1) << 25;
};

/// For every body whose law has a failure criterion with a regularization length: marks
/// each of its points failure_decided_outside and sets matrix_fails_now / fibers_fail_now
/// where the nonlocal mean of the intact phase's measure exceeds its limit. Totally failed
/// points (debris, F reset to a volume change) neither fail again nor count in the means.
/// Call after the deformation update and right before the stress update, which turns the
/// marks into failures. `limit_flags`, when given, holds which limits the points of the bodies
/// the deformation update flagged pass (used up here); the others are checked here.
void decide_nonlocal_failures(const std::vector<const materials::Material*>& body_material,
                              Particles& points, NonlocalFailureCache& cache,
                              FailureLimitFlags* limit_flags = nullptr);

/// The per-body part of what the deformation update flags for the criterion (a criterion for
/// each body whose law asks for the nonlocal one).
FailureLimitFlags failure_limit_flags_for(const std::vector<const materials::Material*>& body_material);

/// Problems of a failure criterion's regularization length (parameter "regularization_length")
/// on a grid of cell size h with n_ranks MPI ranks: the means need l >= h / 2 to hold more than
/// the point itself, and they run on one rank.
std::vector<ParameterProblem> check_regularization(const materials::FailureParameters& failure,
                                                   double cell_size, int n_ranks);

/// Whether any body's law asks for the nonlocal criterion.
bool uses_nonlocal_failure(const std::vector<const materials::Material*>& body_material);
} // namespace vulnus::mpm
