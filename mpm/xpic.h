// XPIC(m), the extended particle-in-cell velocity update (Hammerquist and Nairn 2017,
// "A new method for material point method particle updates that reduces noise and enhances
// stability", Comput. Methods Appl. Mech. Engrg. 318:724-738). PIC gives the points
// S v^(n+1) and so loses every part of their velocities the grid cannot hold; FLIP keeps it
// all, noise included. XPIC(m) keeps the part a grid field fits: with A = S^+ S (read a nodal
// field at the points, scatter it back with their masses, divide by the nodal masses), the
// mass-weighted least-squares grid field of the points' velocities is A^-1 v^n, and XPIC(m)
// takes the first m terms of its series, v*_m = sum_(k<m) (I - A)^k v^n. The points then get
// S (v*_m + v^(n+1) - v^n): PIC for m = 1, and as m grows every velocity field the grid can
// represent (a rigid rotation included) passes unchanged while the part it cannot is removed.
// FMPM(m) (Nairn and Hammerquist 2021, "Material point method simulations using an
// approximate full mass matrix inverse", Comput. Methods Appl. Mech. Engrg. 377:113667) reads
// the same series as the inverse of the consistent mass matrix M = S M_p S^T, M^-1 =
// sum_k (I - A)^k M_L^-1, applied to the new lumped velocities: the points get
// S sum_(k<m) (I - A)^k v^(n+1), PIC for m = 1, with no FLIP increment carried. Every term
// after the first carries no momentum, so both conserve it. The points move with
// S v^(n+1) under both, as under every transfer here.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/grid_to_particle.h"
#include "mpm/grid_update.h"
#include "mpm/particles.h"
#include "mpm/transfer_settings.h"

#include <array>
#include <vector>

namespace vulnus::mpm
{
/// scattered[i, b] = sum_p N_i(x_p) m_p sum_j N_j(x_p) nodal[j, b] over the points of each
/// deformable body b that this stepper advances (zero for the others). Threads by point shares;
/// the caller sums it over ranks.
void scatter_point_values(const Grid& grid, const TransferSettings& transfer,
                          const KinematicsSettings& kinematics, const Particles& particles,
                          const std::vector<Vector3>& nodal, std::vector<Vector3>& scattered,
                          std::vector<std::vector<Vector3>>& per_share);

/// One term of the series: term <- term - scattered / m_i (that is (I - A) term), zero where
/// the node-body has no mass or is rigid, the face conditions applied; correction += term.
/// A term carries no momentum until the faces stop part of it: what they take, m_i times the
/// stopped components, is added to support_impulse by face (this rank's owned nodes), so
/// that the momentum audit books it with the supports.
void next_xpic_term(const Grid& grid, const GridUpdateSettings& settings, const GridFields& fields,
                    const std::vector<Vector3>& scattered, std::vector<Vector3>& term,
                    std::vector<Vector3>& correction, std::array<Vector3, 6>& support_impulse);

/// The starting term: `start` (v^n for XPIC, v^(n+1) for FMPM) where the node-body has mass
/// and is deformable, else zero.
void first_xpic_term(const Grid& grid, const GridUpdateSettings& settings, const GridFields& fields,
                     const std::vector<Vector3>& start, std::vector<Vector3>& term);
} // namespace vulnus::mpm
