// The whole subcycled projectile on every rank of a distributed run: each rank advances all of
// its points (they are few) and keeps its own share afterwards.
#pragma once

#include "mpm/particles.h"
#include "mpm/rank_group.h"

#include <cstddef>
#include <vector>

namespace vulnus::mpm
{
struct GatheredProjectile
{
  Particles points;              ///< every rank's share, in rank order (one body)
  std::vector<Vector3> force;    ///< the contact force on each of them
  std::size_t first_of_mine = 0; ///< where this rank's share starts
};

/// Every rank's `mine` (a one-body container) and its per-point `force`, on every rank.
GatheredProjectile gather_on_every_rank(const RankGroup& ranks, const Particles& mine,
                                        const std::vector<Vector3>& force);
} // namespace vulnus::mpm
