// Cell-averaged volume change of the points (an F-bar for MPM, after Coombs, Charlton, Cortis
// and Augarde 2018): each step's volume ratio dJ = J_new / J_old of a point is replaced by the
// ratio of the summed volumes of the points of its body in its cell, and F by
// (dJ_cell / dJ)^(1/3) F. The cell then carries one volumetric constraint instead of one per
// point, which is what removes volumetric locking of nearly incompressible tissue; the
// isochoric part of F is untouched and the cell's total volume is unchanged. The points then
// carry their cell's mean pressure into the grid forces, so that the forces' work is the
// change of the stored energy (the variational F-bar: the cell's volume is what moves).
// With from_grid_flux the cell's ratio is instead det(I + dt L) of the cell's mean velocity
// gradient, whose trace is the grid velocity's exact flux through the cell's faces, so the
// points of a confined body keep the volume of the cells they fill once they have moved; the
// volumetric forces are then taken on the same mean gradient in the scatter (their pair).
// Cells less than half filled by their points keep the summed change: their far corners are
// light.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/particles.h"
#include "mpm/transfer_settings.h"

#include <cstdint>
#include <vector>

namespace vulnus::mpm
{
/// Per-step scratch of the averaging, kept between steps to avoid reallocation.
struct VolumeAveraging
{
  /// The cell's volume change: false, the summed change of its points' volumes (each from its
  /// own velocity gradient); true, the flux of the grid velocity through the cell's faces.
  bool from_grid_flux = false;
  /// Grid flux applies to cells whose points fill at least this share of them.
  static constexpr double grid_flux_min_fill = 0.5;
  /// Per point: J before the step, and the key of the cell it sat in at the start of the step
  /// (-1: not averaged, e.g. debris, whose law reads J alone, or a point outside the grid).
  std::vector<double> j_old;
  std::vector<std::int64_t> cell;
  /// Per cell key of the box: summed volumes of the averaged points before and after the step.
  std::vector<double> volume_old, volume_new;
  std::vector<std::int64_t> touched;
  /// Per point, its present volume (the sums' terms, filled by the threads).
  std::vector<double> point_volume;
  /// Per point, grid flux's force pair: its volume times its mean stress where the scatter
  /// takes that force on its cell's mean corner gradients, else 0.
  std::vector<double> paired_stress;

  /// Sizes the per-point arrays for n points and the per-cell ones for the grid.
  void prepare(const Grid& grid, std::size_t n_points);
  /// Sizes paired_stress for n points and pairs none of them.
  void clear_pair(std::size_t n_points);
  /// Key of the cell holding x (its lowest node's key), or -1 outside the node box.
  static std::int64_t cell_key(const Grid& grid, const Vector3& x);
  /// The same for a point at s in cell units.
  static std::int64_t cell_key_at(const Grid& grid, const Vector3& s);
};

/// Replaces the volume change of points [begin, end) (one body, F already updated, j_old and
/// cell recorded by the deformation update) by the mean of their cells.
void average_volume_changes(long begin, long end, Particles& particles, VolumeAveraging& scratch);
/// Body `body`'s nodal velocities (indexed slot * n_bodies + body) and the step's update.
struct NodalVelocities
{
  const std::vector<Vector3>& velocity;
  const std::vector<NodeBodyData>& node_data;
  std::size_t n_bodies, body;
  double time_step;
  bool midpoint;
};
/// average_volume_changes with each cell's volume ratio over the step taken from the
/// cell-mean gradient L of the nodal velocities: det(I + dt L) or, with `midpoint`,
/// det(I + dt L / 2) / det(I - dt L / 2). A cell less than grid_flux_min_fill full, or with a
/// node where the body has no mass, keeps its points' summed change.
void impose_grid_flux_volume_changes(const Grid& grid, const NodalVelocities& nodal, long begin,
                                     long end, Particles& particles, VolumeAveraging& scratch);
/// Grid flux's force pair, before the scatter (after the node marking): for the points
/// [begin, end) of one body in cells the grid flux applies to (filled, every corner active),
/// the point's volume times its mean stress into scratch.paired_stress, else 0, and its cell
/// into scratch.cell. particles_to_grid (GridFluxPair) then takes that part of the point's
/// internal force on its cell's mean corner gradients instead of its own shape gradients, so
/// the volumetric forces' power is the mean stress times the rate of the grid flux's volume.
void prepare_grid_flux_pair(const Grid& grid, long begin, long end, const Particles& particles,
                            VolumeAveraging& scratch);
/// After the scatter: gives the paired points [begin, end) of body `body` whose cell has a
/// corner where the body has no mass their own volumetric force back, since
/// impose_grid_flux_volume_changes leaves such cells to the summed change. Returns how many.
/// It reads the rank's own masses, before the neighbours' sums: a corner the rank's points
/// give exactly zero weight but a neighbour's reach would stay unpaired here and get the flux
/// there (linear shapes, every point of the cell on its lower face; not met in practice).
long unpair_cells_without_mass(const Grid& grid, const TransferSettings& transfer,
                               std::size_t body, long begin, long end, const Particles& particles,
                               GridFields& fields, VolumeAveraging& scratch);
/// Replaces the pressure of points [begin, end) (one body) by the volume-weighted mean
/// pressure of the points of their cell (at their present positions), debris excepted.
void average_cell_pressures(const Grid& grid, long begin, long end, Particles& particles,
                            VolumeAveraging& scratch);
} // namespace vulnus::mpm
