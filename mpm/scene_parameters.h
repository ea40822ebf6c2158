// Plain structs describing an MPM scene: the neutral scene description (bodies, materials,
// faces) plus the grid's numerics, contact and time stepping; built by the deck reader and
// consumed by the MPM solver. SI units.
#pragma once

#include "mpm/grid_axis.h"
#include "scene/scene_description.h"

namespace vulnus::mpm
{
using scene::Vector3;

enum class ShapeFunction
{
  linear,
  gimp, ///< uGIMP: a fixed box per point
  cpdi  ///< CPDI1: a parallelepiped per point that deforms with its F
};

/// The shape functions' name in logs and messages.
inline const char* shape_function_name(const ShapeFunction shape)
{
  return shape == ShapeFunction::linear ? "linear" : shape == ShapeFunction::gimp ? "GIMP" : "CPDI";
}

enum class UpdateScheme
{
  usl, ///< update stress last
  musl ///< modified update stress last (velocities re-mapped before the stress update)
};

/// How points take their new velocity from the grid (Jiang et al. 2015 for APIC).
enum class VelocityTransfer
{
  /// FLIP velocities relaxed towards APIC's over a fixed physical time (not per step):
  /// dv_p/dt = FLIP - (v_p - sum w v_i) / tau, with the affine part C_p for the scatter
  relaxed_apic,
  /// The same relaxation towards the PIC velocity, without the affine part
  relaxed_pic,
  apic, ///< v_p = sum w v_i, plus the affine part C_p = grad v at the point for the scatter
  flip, ///< v_p += sum w (v_i^(n+1) - v_i^n): no damping, overshoots where nodes jump
  pic,  ///< v_p = sum w v_i: damps every mode the grid cannot hold, including rotation
  /// XPIC(m) (mpm/xpic.h): PIC plus the part of the points' velocities a grid field fits,
  /// from m terms of a series; removes FLIP's noise without PIC's damping of resolved motion
  xpic,
  /// FMPM(m) (mpm/xpic.h): PIC from the new grid velocities the consistent mass matrix would
  /// give, its inverse approximated by m terms of the same series; no FLIP memory
  fmpm
};

/// How the deformation gradient follows the velocity gradient L over one step.
enum class DeformationUpdate
{
  midpoint,     ///< F <- (I - dt L / 2)^-1 (I + dt L / 2) F: exact for rigid spin, 2nd order
  forward_euler ///< F <- (I + dt L) F: stretches a spinning point by (1 + (w dt)^2)^(1/2)
};

using scene::BodyParameters;
using scene::BodyShape;
using scene::FaceCondition;
using scene::FaceConditions;
using scene::find_material;
using scene::NamedMaterial;
using scene::NoseShape;
using scene::RigidMotion;

struct ContactParameters
{
  /// false: the bodies share one velocity field (no-slip at every node they share).
  bool enabled = true;
  /// Bodies pass through each other (no interaction at all); not a deck choice, for tests
  /// of the transfers that need independent bodies.
  bool ignore_other_bodies = false;
  double friction_coefficient = 0.08; ///< Coulomb; negative means no-slip (single velocity field)
  /// Proximity check, in cell sizes (0: off): bodies interact at a node only when their mass
  /// centres there are at most this far apart along the normal after the step's approach.
  double proximity_distance = 0.8;
  /// A rigid body's gap (and normal) from its exact shape moved with it, to the other body's
  /// mass centre at the node less half that body's point spacing, instead of the mass
  /// centres both bodies' points give the node (proximity_distance then applies to
  /// deformable pairs only).
  bool exact_rigid_surface = false;
  /// Uintah's friction_bard criterion: bodies also interact at a node where a body's surface
  /// is in compression (n . sigma n < 0 of its nodal stress sum), even while they separate.
  bool hold_compressed_surfaces = false;
  /// Uintah's two passes: the projected velocities are corrected too, before the forces act.
  bool two_passes = false;
};

/// The scene and the MPM numerics: the background grid is a structured grid of cubic cells of
/// cell_size covering [domain_min, domain_max], or a graded one (mpm/grid_axis.h).
struct SceneParameters : scene::SceneDescription
{
  /// Cells wider than cell_size outside a fine box (Grid/Grading); disabled by default.
  GridGrading grading;
  ShapeFunction shape_function = ShapeFunction::linear;
  UpdateScheme update_scheme = UpdateScheme::musl;
  ContactParameters contact;
  double cfl = 0.4;
  VelocityTransfer velocity_transfer = VelocityTransfer::flip;
  /// relaxed_apic: tau in units of the Courant time h / max(c + |v|) (the CFL-1 step).
  double velocity_relaxation = 1.0;
  /// XPIC and FMPM: the number m of the series' terms (1 is PIC; each further term is one
  /// more pass over the points).
  int series_order = 5;
  /// A deformable projectile's points relax their FLIP velocity towards PIC over this many of
  /// the projectile's own Courant times h / max(c + |v|) (0: it uses velocity_transfer). A
  /// stiff projectile rings at its own grid-scale frequency after each contact impulse; FLIP
  /// never damps that ringing, which then yields the metal numerically.
  double projectile_velocity_relaxation = 0.0;
  /// A deformable projectile advances in substeps of its own CFL step inside the scene's
  /// step, which then follows the other bodies' wave speeds (contact is resolved once per
  /// scene step, with the projectile as the contact leader: see mpm/projectile_subcycle.h).
  bool subcycle_projectile = true;
  /// The subcycled projectile's substeps are h / max(c + |v|) times this (0: cfl). Its
  /// elastic response reaches the wound only through the contact, so 0.4 changes no wound
  /// figure by more than a halving of the scene's step does (docs/converged_wound.md).
  double projectile_cfl = 0.4;
  /// A deformable projectile whose law has a yield stress moves as a rigid body while the
  /// contact keeps it far below yield, and turns deformable at the first step that does not
  /// (mpm/rigid_hold.h): the stress limit is the fraction of its yield stress the averaged
  /// contact pressure may reach.
  bool rigid_projectile_while_elastic = false;
  double rigid_projectile_stress_limit = 0.5;
  DeformationUpdate deformation_update = DeformationUpdate::midpoint;
  /// Each step's volume change of a point replaced by its cell's (mpm/volume_averaging.h):
  /// free of volumetric locking for nearly incompressible tissue.
  bool cell_volume_averaging = false;
  /// With cell_volume_averaging: the cell's volume change from the grid velocity's flux
  /// through its faces instead of its points' summed volumes.
  bool cell_volume_from_grid_flux = false;
  double artificial_viscosity_linear = 0.0;    ///< bulk viscosity coefficients (0 = off)
  double artificial_viscosity_quadratic = 0.0;
  double max_time_step = 1.0;          ///< s, cap
  double min_time_step = 1.0e-12;      ///< s, floor: below it the run stops as a blow-up
  unsigned int sort_interval = 50;     ///< steps between re-sorting particles by cell
  unsigned int n_threads = 0;          ///< 0: all available
  bool stop_when_projectile_exits = true;
  /// End the run once the projectile, inside the target, has slowed to stop_speed (m/s) along
  /// its flight or turned back (Time/Stop when projectile stops).
  bool stop_when_projectile_stops = false;
  double projectile_stop_speed = 1.0;
  /// Points that leave the grid: removed (their energy and momentum booked as outflow) or,
  /// when false, the run stops as a blow-up.
  bool remove_points_leaving_grid = false;
  /// A deformable body's point splits in two once an edge of its domain is longer than this
  /// many cells (mpm/point_splitting.h); 0: never.
  double point_split_edge_cells = 0.0;
  /// The scene turns about the y axis (x = z = 0) and is solved in its r-y half plane
  /// (mpm/axisymmetry.h): points are rings, the grid one cell thick.
  bool axisymmetric = false;
  /// The bodies as the deck draws them, when the MPM scene holds only a part of one (a
  /// hybrid's zone): the projectile's path enters and leaves the target through their
  /// surfaces. Empty: `bodies`.
  std::vector<BodyParameters> deck_bodies;
};
} // namespace vulnus::mpm
