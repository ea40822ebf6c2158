// Deck-level description of a hybrid MPM-FE scene (docs/DESIGN.md section 6): the MPM zone around
// the tract, which body it splits, and the coupling scheme. SI units.
#pragma once

#include "fem/fem_parameters.h"

#include <array>
#include <string>

namespace vulnus::coupling
{
enum class CouplingScheme
{
  same_step, ///< scheme 1: one time step, interface nodes shared (masses and forces summed)
  multi_step ///< scheme 2: the FE side takes steps of several MPM substeps
};

/// How the MPM substeps of a window meet an implicit far field (docs/far_field.md, section 1).
enum class WindowCoupling
{
  /// The substeps move the interface towards the end velocities that would balance the
  /// window; the window is kept within one wave transit of the far field's smallest cell.
  balanced,
  /// The substeps see the far field as its mean free interface velocity over the window
  /// plus a dashpot of its effective interface mass: stable for any window length.
  dashpot
};

/// Where the MPM zone starts: the deck's box, or the bullet path's tube (radius plus one
/// cell plus a margin) through the body, on grid nodes.
enum class ZoneStart
{
  box,
  around_path
};

/// Where the far field's interface nodes meet the MPM grid (docs/hybrid_interface.md).
enum class InterfacePlacement
{
  /// Each interface node is the grid node it started on, for the whole run: the coupling
  /// assumes the interface moves a small fraction of a cell.
  grid_nodes,
  /// Each interface node is spread over the grid nodes around where it is now, like a
  /// material point, at every step or window start: the interface may move any distance.
  following
};

/// Which motion of an interface node converts its cell.
enum class InterfaceMotion
{
  total,
  non_affine
};

/// Adaptive zone (docs/adaptive_zone.md): far-field cells whose material nears failure turn
/// into material points, the zone box growing to hold them.
struct AdaptiveZoneParameters
{
  bool enabled = false;
  /// A cell converts when a quadrature point reaches this fraction of the failure criterion
  /// (matrix shear over its limit, fiber stretch - 1 over limit - 1) or has failed, as
  /// `failure` measures it.
  double threshold = 0.5;
  /// Of which failure: any (matrix or fibers; a point that failed at all converts its cell),
  /// or total (both; the far field carries partial failure, fem::FailureProximity).
  fem::FailureProximity failure = fem::FailureProximity::any_failure;
  /// Whether the far field carries partial failure and counts total failures only.
  bool total_failure_rule() const { return failure == fem::FailureProximity::total_failure; }
  /// A cell also converts when an interface node of it has moved this fraction of a grid
  /// cell (the shared grid node stays put: the coupling assumes small interface motion):
  /// its whole displacement, or its departure from its cell's best-fit affine motion, which
  /// waves and rigid motion do not make.
  double interface_displacement = 0.1;
  InterfaceMotion interface_motion = InterfaceMotion::total;
  /// A cell converts when its best-fit affine stretch exceeds ln(lambda_max / lambda_min) =
  /// this (0: not checked) or its smallest corner Jacobian falls below this fraction of its
  /// largest (0: not checked).
  double distortion = 0.0;
  double jacobian_ratio = 0.0;
  /// The zone grows to hold a converting cell with this many cells around it.
  unsigned int margin_cells = 2;
  /// How far beyond its start the zone may grow on every side, m; the far-field mesh has
  /// the grid's cells there.
  double reach = 0.01;
  /// MPM steps between checks (at the end of an FE window).
  unsigned int check_interval = 10;
};

struct HybridParameters
{
  bool enabled = false;
  /// The MPM zone, a box on MPM grid nodes; the rest of the split body is finite elements.
  std::array<double, 3> zone_min{{0.0, 0.0, 0.0}};
  std::array<double, 3> zone_max{{0.0, 0.0, 0.0}};
  /// Name of the body split into MPM zone and FE far field; empty: the only deformable box
  /// body that is not the projectile.
  std::string body;
  CouplingScheme scheme = CouplingScheme::same_step;
  /// multi_step: MPM substeps per FE step; 0 chooses the FE step from its own stability
  /// (explicit) or the deck step (implicit).
  unsigned int substeps = 0;
  WindowCoupling window_coupling = WindowCoupling::balanced;
  InterfacePlacement interface = InterfacePlacement::grid_nodes;
  ZoneStart zone_start = ZoneStart::box;
  /// around_path: the tissue kept around the projectile's radius plus one cell, m.
  double path_margin = 0.002;
  AdaptiveZoneParameters adaptive;
  /// A failed far-field quadrature point stops the run (else it warns and goes on).
  bool stop_when_fe_points_fail = true;
};
} // namespace vulnus::coupling
