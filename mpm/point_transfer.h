// Moving material points between containers (no MPI here): picking points out by a per-point
// destination, flattening a container to bytes and back, and appending one container's
// bodies to another's. Distributed runs send the bytes between ranks.
#pragma once

#include "mpm/particles.h"

#include <vector>

namespace vulnus::mpm
{
/// The points whose destination equals d, for each d in [0, n_destinations), body ranges
/// kept; points with a negative destination go nowhere.
std::vector<Particles> split_by_destination(const Particles& points, const std::vector<int>& destination,
                                            int n_destinations);

/// All arrays and the body ranges as bytes; from_bytes reverses it and throws
/// std::runtime_error on a size mismatch.
std::vector<char> to_bytes(const Particles& points);
Particles from_bytes(const char* data, std::size_t size);

/// The points flagged in `keep`, then those of each `incoming` container, body by body, in
/// one copy (incoming containers are empty or have the same bodies).
Particles merge_points(const Particles& points, const std::vector<char>& keep,
                       const std::vector<Particles>& incoming);

/// The same result as merge_points (up to the order of points within a body) without copying
/// the container: holes left by the points not kept take incoming points or the body's last
/// points, and bodies shift by moving at most as many points as the shift. The work is
/// proportional to the points moved, not to the container.
void exchange_in_place(Particles& points, const std::vector<char>& keep,
                       const std::vector<Particles>& incoming);

/// Appends the points of `more` body by body (both must have the same number of bodies).
void append_points(Particles& points, const Particles& more);
} // namespace vulnus::mpm
