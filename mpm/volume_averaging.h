// Cell-averaged volume change of the points (an F-bar for MPM, after Coombs, Charlton, Cortis
// and Augarde 2018): each step's volume ratio dJ = J_new / J_old of a point is replaced by the
// ratio of the summed volumes of the points of its body in its cell, and F by
// (dJ_cell / dJ)^(1/3) F. The cell then carries one volumetric constraint instead of one per
// point, which is what removes volumetric locking of nearly incompressible tissue; the
// isochoric part of F is untouched and the cell's total volume is unchanged. The points then
// carry their cell's mean pressure into the grid forces, so that the forces' work is the
// change of the stored energy (the variational F-bar: the cell's volume is what moves).
#pragma once

#include "mpm/grid.h"
#include "mpm/particles.h"

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
/// Per-step scratch of the averaging, kept between steps to avoid reallocation.
struct VolumeAveraging
{
  /// Per point: J before the step, and the key of the cell it sat in at the start of the step
  /// (-1: not averaged, e.g. debris, whose law reads J alone, or a point outside the grid).
  std::vector<double> j_old;
  std::vector<std::int64_t> cell;
  /// Per cell key of the box: summed volumes of the averaged points before and after the step.
  std::vector<double> volume_old, volume_new;
  std::vector<std::int64_t> touched;

  /// Sizes the per-point arrays for n points and the per-cell ones for the grid.
  void prepare(const Grid& grid, std::size_t n_points);
  /// Key of the cell holding x (its lowest node's key), or -1 outside the node box.
  static std::int64_t cell_key(const Grid& grid, const Vector3& x);
};

/// Replaces the volume change of points [begin, end) (one body, F already updated, j_old and
/// cell recorded by the deformation update) by the mean of their cells.
void average_volume_changes(long begin, long end, Particles& particles, VolumeAveraging& scratch);
/// Replaces the pressure of points [begin, end) (one body) by the volume-weighted mean
/// pressure of the points of their cell (at their present positions), debris excepted.
void average_cell_pressures(const Grid& grid, long begin, long end, Particles& particles,
                            VolumeAveraging& scratch);
} // namespace vulnus::mpm
