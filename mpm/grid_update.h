// Grid update stage: nodal velocities before and after the internal forces, multi-velocity
// field contact between bodies (Bardenhagen et al. 2000, Coulomb friction), rigid bodies, and
// the face boundary conditions of the domain.
#pragma once

#include "mpm/grid.h"
#include "mpm/grid_fields.h"
#include "mpm/scene_parameters.h"

#include <functional>
#include <array>
#include <vector>

namespace vulnus::mpm
{
struct GridUpdateSettings
{
  double time_step = 0.0;
  Vector3 gravity = Vector3::Zero();
  FaceConditions faces{};
  bool contact = false;
  /// Coulomb coefficient; negative: no-slip (all bodies share the centre-of-mass velocity).
  double friction_coefficient = 0.0;
  std::vector<char> body_is_rigid;     ///< per body
  std::vector<Vector3> rigid_velocity; ///< per body, used when rigid
  double mass_tolerance = 0.0;         ///< node-body entries lighter than this are ignored
  /// A deformable body far stiffer than the others, advanced in substeps of its own (a
  /// subcycled projectile), or -1. Where it meets them and no rigid body is present it leads:
  /// their velocities are corrected towards its nodal velocity as towards a rigid body's, and
  /// its own nodal velocity takes the reaction (the momentum they gained). Its trial velocity
  /// leaves out its internal forces, and the contact dissipation leaves out its kinetic
  /// energy change, which its substeps book as work.
  int subcycled_body = -1;
  /// Proximity check of contact (m; 0: off): two bodies at a node interact only when the
  /// distance along the normal between their mass centres there, after this step's approach,
  /// is at most this. Without it contact acts wherever both bodies have mass, up to a cell
  /// before their surfaces meet.
  double contact_distance = 0.0;
  /// Half-width (m) of the band around contact_distance over which the correction fades in.
  double contact_band = 0.0;
  /// Per body: its exact shape when contact measures the gap from a rigid body's surface
  /// (Contact/Rigid surface = exact; used while the body is rigid), else null. A node then
  /// engages when the other body's mass centre there, less half its point spacing, reaches
  /// that surface after the step's approach; the surface gives the normal. Without it the gap
  /// is between the two bodies' mass centres (contact_distance).
  std::vector<const BodyParameters*> exact_surface;
  std::vector<Vector3> rigid_offset;       ///< per body: how far its exact shape has moved, m
  std::vector<double> point_half_spacing;  ///< per body: half its point spacing, m
  /// Contact also where a body's surface is in compression, n . S n < 0 with S its nodal
  /// stress sum (GridFields::stress_sum), even while the bodies separate (Uintah's criterion).
  bool hold_compressed_surfaces = false;
  /// Contact also corrects the projected velocities v^n before the forces act (Uintah's
  /// friction_bard, two passes); the points' FLIP increments then leave that correction out.
  /// Not with a subcycled body.
  bool correct_projected_velocities = false;
  /// When set (distributed runs), contact sums count only the nodes this rank owns.
  std::function<bool(std::int64_t)> owns_node;
};

struct GridUpdateResult
{
  std::vector<Vector3> contact_force; ///< per body, force the others exert on it (N)
  /// Per rigid body, the largest contact force the others exert on it at one node (N).
  std::vector<double> peak_node_force;
  /// Per rigid body, the moment of the contact forces about the point x = 0 (N m).
  std::vector<Vector3> contact_moment;
  double contact_dissipation = 0.0;   ///< kinetic energy removed by contact this step (J)
  std::size_t n_contact_nodes = 0;    ///< nodes where two or more bodies met
  /// Two rigid bodies at one node (neither can give way: not modelled): the lowest such node
  /// key and the pair of bodies, or -1.
  std::int64_t rigid_meeting_node = -1;
  std::size_t rigid_meeting_bodies[2] = {0, 0};
  /// Impulse the domain faces' supports gave the deformable bodies this step, by face (x-, x+,
  /// y-, y+, z-, z+), N s: m (v_after - v_before) of the face conditions at this rank's nodes.
  std::array<Vector3, 6> support_impulse = {Vector3::Zero(), Vector3::Zero(), Vector3::Zero(),
                                            Vector3::Zero(), Vector3::Zero(), Vector3::Zero()};
};

/// Computes fields.velocity (v^n) and fields.velocity_new (v^(n+1)) of every node and body,
/// with the face conditions, except at nodes where bodies meet when contact is on; books the
/// supports' impulse there into result.support_impulse (zeroed first) and, when a face is not
/// free, their velocity change into fields.support_change (zero elsewhere).
void update_grid(const Grid& grid, const GridUpdateSettings& settings, GridFields& fields,
                 GridUpdateResult& result);

/// Corrects v^(n+1) at the nodes where two or more bodies have mass (contact on), then applies
/// the face conditions there; fills the contact force, dissipation and node count. There the
/// supports' change is what they take from the trial velocity (the contact's change is what is
/// left of the correction after them), so the two sum to the node's whole correction.
void resolve_contacts(const Grid& grid, const GridUpdateSettings& settings, GridFields& fields,
                      GridUpdateResult& result);

/// Whether a face is fixed or a roller (its supports can take kinetic energy).
bool any_support(const FaceConditions& faces);

/// Applies the domain face conditions to a nodal velocity of node `key`.
void apply_face_conditions(const Grid& grid, const FaceConditions& faces, std::int64_t key,
                           Vector3& velocity);
/// The same, adding the impulse mass * (change of velocity) to the face that imposed it: on an
/// edge or corner each component to the supported face normal to it, a component no supported
/// face is normal to to the node's first fixed face.
void apply_face_conditions(const Grid& grid, const FaceConditions& faces, std::int64_t key,
                           double mass, Vector3& velocity, std::array<Vector3, 6>& impulse);

/// Re-derives nodal velocities from fields.projected_momentum and the nodal masses (MUSL) into
/// fields.velocity (v^n is not needed any more then; fields.velocity_new still moves the
/// points), with the face conditions and rigid velocities applied.
void velocities_from_momenta(const Grid& grid, const GridUpdateSettings& settings,
                             GridFields& fields);
} // namespace vulnus::mpm
