// Nodal velocity update, multi-velocity-field frictional contact, boundary conditions.
#include "mpm/grid_update.h"

#include "mpm/particles.h"
#include "mpm/shape_distance.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace vulnus::mpm
{
bool any_support(const FaceConditions& faces)
{
  return std::any_of(faces.begin(), faces.end(),
                     [](const FaceCondition c) { return c != FaceCondition::free; });
}

void apply_face_conditions(const Grid& grid, const FaceConditions& faces, const std::int64_t key,
                           Vector3& velocity)
{
  const auto ijk = grid.node_ijk(key);
  const auto& n = grid.cells();
  for (int d = 0; d < 3; ++d)
  {
    const FaceCondition lower = faces[2 * d], upper = faces[2 * d + 1];
    const bool on_lower = ijk[d] <= 0, on_upper = ijk[d] >= n[d];
    const FaceCondition c = on_lower ? lower : (on_upper ? upper : FaceCondition::free);
    if (c == FaceCondition::fixed)
    {
      velocity.setZero();
      return;
    }
    if (c == FaceCondition::roller || c == FaceCondition::symmetry)
      velocity[d] = 0.0;
  }
}

void apply_face_conditions(const Grid& grid, const FaceConditions& faces, const std::int64_t key,
                           const double mass, Vector3& velocity, std::array<Vector3, 6>& impulse)
{
  const auto ijk = grid.node_ijk(key);
  const auto& n = grid.cells();
  // The supported face of this node on each axis, and its first fixed face.
  int face_on_axis[3] = {-1, -1, -1};
  int first_fixed = -1;
  for (int d = 0; d < 3; ++d)
  {
    const bool on_lower = ijk[d] <= 0, on_upper = ijk[d] >= n[d];
    if (!on_lower && !on_upper)
      continue;
    const int face = on_lower ? 2 * d : 2 * d + 1;
    if (faces[face] != FaceCondition::free)
      face_on_axis[d] = face;
    if (faces[face] == FaceCondition::fixed && first_fixed < 0)
      first_fixed = face;
  }
  // A node on an edge or corner books each component on the face normal to it (the z- face's
  // normal reaction at the x-/z- edge is the z- face's), a tangential one on its fixed face.
  for (int d = 0; d < 3; ++d)
  {
    const bool stopped = first_fixed >= 0 || face_on_axis[d] >= 0;
    if (!stopped)
      continue;
    const int face = face_on_axis[d] >= 0 ? face_on_axis[d] : first_fixed;
    impulse[face][d] -= mass * velocity[d];
    velocity[d] = 0.0;
  }
}

namespace
{
/// n . S n below minus this (Pa, a stress sum) counts as compression: Uintah's 1e-12.
constexpr double compression_floor = 1e-12;

/// The nodal stress sums of the bodies at active node `node`, when the compression criterion
/// reads them, else null.
const SymmetricTensor* nodal_stress(const GridUpdateSettings& s, const GridFields& fields,
                                    const long node)
{
  return s.hold_compressed_surfaces ? &fields.stress_sum[node * fields.n_bodies] : nullptr;
}

/// Separation along `normal` (the first body's outward normal) of two bodies' mass centres
/// seen from a node, at the end of the step if nothing acted between them (`closing`: their
/// approach speed along the normal).
double gap_after_step(const NodeBodyData& first, const NodeBodyData& second,
                      const Vector3& normal, const double closing, const double dt)
{
  const Vector3 separation =
    second.mass_position / second.mass - first.mass_position / first.mass;
  return separation.dot(normal) - dt * closing;
}

/// Share of the contact correction applied at a node where a body meets rigid body `rigid`,
/// whose exact surface is known: from the gap between that surface and the other body's mass
/// centre there, less half its point spacing, after the step's approach; `normal` becomes the
/// surface's outward normal. Negative when the surface gives no normal there.
double exact_surface_engagement(const GridUpdateSettings& s, const NodeBodyData* data,
                                const Vector3* v, const std::size_t rigid,
                                const std::size_t other, Vector3& normal)
{
  const Vector3 x_other = data[other].mass_position / data[other].mass;
  const ShapeDistance surface =
    distance_to_shape(*s.exact_surface[rigid], s.rigid_offset[rigid], x_other);
  if (!(surface.normal.squaredNorm() > 0.0))
    return -1.0;
  normal = surface.normal;
  const double closing = (v[rigid] - v[other]).dot(normal);
  const double gap = surface.distance - s.point_half_spacing[other] - s.time_step * closing;
  return std::clamp((s.contact_band - gap) / (2.0 * s.contact_band), 0.0, 1.0);
}

/// Corrects the velocities of the bodies meeting at one node. `v` holds the trial
/// velocities of the n_bodies entries; returns the kinetic energy removed. With `body_change`,
/// the deformable bodies' velocity changes are written there (the subcycled body's stays zero)
/// and only the work their changes do against v_cm (the rigid body's or leader's energy
/// transfer, zero between deformable bodies) is returned: the energy the points lose is booked
/// where they take their velocities, from these changes (update_point_kinematics).
double resolve_contact(const GridUpdateSettings& s, const NodeBodyData* data,
                       const SymmetricTensor* stress, Vector3* v, const std::size_t n_bodies,
                       Vector3* contact_force_local, Vector3* body_change = nullptr)
{
  // Centre-of-mass velocity, or the velocity of the rigid body, else of the contact leader,
  // when one is present (both are called rigid below: the others follow them).
  double total_mass = 0.0;
  Vector3 total_momentum = Vector3::Zero();
  int rigid = -1;
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    if (data[b].mass <= s.mass_tolerance)
      continue;
    if (s.body_is_rigid[b])
      rigid = static_cast<int>(b);
    total_mass += data[b].mass;
    total_momentum += data[b].mass * v[b];
  }
  const int leader_here = s.subcycled_body >= 0 && data[s.subcycled_body].mass > s.mass_tolerance
                            ? s.subcycled_body
                            : -1;
  if (rigid < 0)
    rigid = leader_here;
  const bool leader = rigid >= 0 && rigid == s.subcycled_body;
  const Vector3 v_cm = rigid < 0 ? Vector3(total_momentum / total_mass)
                       : leader  ? v[rigid]
                                 : s.rigid_velocity[rigid];

  // Outward unit normals: for two bodies one shared direction from the mass gradients.
  std::size_t present[2] = {0, 0};
  std::size_t n_present = 0;
  for (std::size_t b = 0; b < n_bodies; ++b)
    if (data[b].mass > s.mass_tolerance)
    {
      if (n_present < 2)
        present[n_present] = b;
      ++n_present;
    }
  const bool pair = n_present == 2;
  Vector3 pair_normal = Vector3::Zero();
  if (pair)
  {
    // sum_p m_p grad N_i(x_p) points from a body's points towards the node: outward. A rigid
    // body's surface is the better-defined one, so its normal alone is used when present.
    Vector3 g = data[present[0]].mass_gradient - data[present[1]].mass_gradient;
    if (rigid == static_cast<int>(present[0]))
      g = data[present[0]].mass_gradient;
    else if (rigid == static_cast<int>(present[1]))
      g = -data[present[1]].mass_gradient;
    const double norm = g.norm();
    if (norm > 0.0)
      pair_normal = g / norm; // outward normal of the first body
  }

  const double dt = s.time_step;
  // Share of the contact correction applied: 1 for bodies in contact, 0 for bodies apart.
  double engagement = 1.0;
  const bool exact = pair && rigid >= 0 && !leader && s.friction_coefficient >= 0.0 &&
                     !s.exact_surface.empty() && s.exact_surface[rigid];
  Vector3 surface_normal = Vector3::Zero();
  const double surface_engagement =
    exact ? exact_surface_engagement(s, data, v, rigid,
                                     present[0] == std::size_t(rigid) ? present[1] : present[0],
                                     surface_normal)
          : -1.0;
  if (surface_engagement >= 0.0)
  {
    pair_normal = present[0] == std::size_t(rigid) ? surface_normal : Vector3(-surface_normal);
    engagement = surface_engagement;
    if (engagement == 0.0)
      return 0.0;
  }
  else if (pair && s.contact_distance > 0.0 && s.friction_coefficient >= 0.0 &&
           pair_normal.squaredNorm() > 0.0)
  {
    // The correction fades in linearly over a band around the contact distance, so that
    // round-off in the separation changes the result by round-off, not by a whole impulse.
    const double closing = (v[present[0]] - v[present[1]]).dot(pair_normal);
    const double gap = gap_after_step(data[present[0]], data[present[1]], pair_normal, closing, dt);
    const double band = s.contact_band;
    engagement = std::clamp((s.contact_distance + band - gap) / (2.0 * band), 0.0, 1.0);
    if (engagement == 0.0)
      return 0.0; // apart: each body keeps its own velocity
  }

  double dissipated = 0.0;
  Vector3 reaction = Vector3::Zero(); // momentum the followers gained
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    const double m = data[b].mass;
    if (m <= s.mass_tolerance || (rigid >= 0 && static_cast<int>(b) == rigid))
      continue;
    Vector3 normal;
    if (pair)
      normal = b == present[0] ? pair_normal : Vector3(-pair_normal);
    else
    {
      const double norm = data[b].mass_gradient.norm();
      normal = norm > 0.0 ? Vector3(data[b].mass_gradient / norm) : Vector3::Zero();
    }
    const Vector3 before = v[b];
    const Vector3 relative = v[b] - v_cm;
    if (s.friction_coefficient < 0.0)
      v[b] = v_cm;
    else
    {
      const double approach = relative.dot(normal);
      // Separating bodies move independently, unless the compression criterion holds a
      // compressed surface (the correction then removes the separation).
      if (approach <= 0.0 &&
          !(stress && normal.dot(full_tensor(stress[b]) * normal) < -compression_floor))
        continue;
      const Vector3 tangential = relative - approach * normal;
      const double slip = tangential.norm();
      const double friction_limit = s.friction_coefficient * std::abs(approach);
      if (slip <= friction_limit)
        v[b] = v_cm; // sticking
      else
        v[b] -= approach * normal + friction_limit * (tangential / slip);
    }
    v[b] = before + engagement * (v[b] - before);
    const Vector3 force = m * (v[b] - before) / dt;
    reaction += m * (v[b] - before);
    contact_force_local[b] += force;
    if (rigid >= 0)
      contact_force_local[rigid] -= force;
    // Without body_change: kinetic energy lost relative to the centre of mass (equals the
    // total loss because the corrections conserve momentum, and counts work done on a rigid
    // body as a transfer). With it, and for the subcycled body: that transfer alone.
    if (body_change && static_cast<int>(b) != s.subcycled_body)
      body_change[b] = v[b] - before;
    if (body_change || static_cast<int>(b) == s.subcycled_body)
      dissipated += v_cm.dot(m * (v[b] - before)); // see below
    else
      dissipated += 0.5 * m * ((before - v_cm).squaredNorm() - (v[b] - v_cm).squaredNorm());
  }
  if (leader)
  {
    // The leader's node takes the reaction, which its substeps spread over its points (see
    // mpm/projectile_subcycle.h).
    const Vector3 change = -reaction / data[rigid].mass;
    v[rigid] += change;
    dissipated += v_cm.dot(data[rigid].mass * change);
  }
  // The subcycled body's velocity changes over its substeps, not here: its term is the
  // transfer v_cm . dp, so that the sum is the others' loss in the lab frame; the substeps
  // subtract the work the contact force does on it.
  return dissipated;
}
/// Whether two rigid bodies reaching one node touch there: their mass centres seen from the
/// node, after the step's approach, within the contact proximity distance along the normal
/// (any shared node when the check is off).
bool rigid_bodies_touch(const GridUpdateSettings& s, const NodeBodyData* data,
                        const std::size_t first, const std::size_t second)
{
  if (!(s.contact_distance > 0.0))
    return true;
  const Vector3 g = data[first].mass_gradient - data[second].mass_gradient;
  if (!(g.norm() > 0.0))
    return true;
  const Vector3 normal = g.normalized(); // outward of the first body
  const double closing = (s.rigid_velocity[first] - s.rigid_velocity[second]).dot(normal);
  return gap_after_step(data[first], data[second], normal, closing, s.time_step) <=
         s.contact_distance;
}
/// The supports' share of a node's velocity change over a step, from v^n through the forces'
/// trial to the supported end: the whole change of each stopped component, the forces' share
/// included. The strain energy sees a stopped node at rest, so the kinetic energy the forces
/// would have given it there is not the material's but the supports'.
Vector3 stopped_change(const Grid& grid, const FaceConditions& faces, const std::int64_t key,
                       const Vector3& start, const Vector3& trial, const Vector3& supported)
{
  Vector3 free_increment = trial - start;
  apply_face_conditions(grid, faces, key, free_increment);
  return supported - start - free_increment;
}
} // namespace

void update_grid(const Grid& grid, const GridUpdateSettings& s, GridFields& fields,
                 GridUpdateResult& result)
{
  const std::size_t n_bodies = fields.n_bodies;
  const long n_nodes = static_cast<long>(grid.n_active());
  const double dt = s.time_step;
  result.support_impulse.fill(Vector3::Zero());
  const bool supports = any_support(s.faces);
  if (supports)
    fields.support_change.resize(fields.velocity_new.size());
#pragma omp parallel
  {
  std::array<Vector3, 6> impulse_local, impulse_elsewhere; // another rank's node
  impulse_local.fill(Vector3::Zero());
  impulse_elsewhere.fill(Vector3::Zero());
  std::vector<Vector3> unbooked_force(n_bodies, Vector3::Zero());
#pragma omp for schedule(static)
  for (long node = 0; node < n_nodes; ++node)
  {
    const std::int64_t key = grid.active_keys()[node];
    const NodeBodyData* data = &fields.data[node * n_bodies];
    Vector3* v = &fields.velocity[node * n_bodies];
    Vector3* v_new = &fields.velocity_new[node * n_bodies];
    Vector3* change = supports ? &fields.support_change[node * n_bodies] : nullptr;
    std::size_t n_with_mass = 0;
    for (std::size_t b = 0; b < n_bodies; ++b)
    {
      if (change)
        change[b].setZero();
      if (data[b].mass <= s.mass_tolerance)
      {
        v[b].setZero();
        v_new[b].setZero();
        continue;
      }
      ++n_with_mass;
      if (s.body_is_rigid[b])
      {
        v[b] = s.rigid_velocity[b];
        v_new[b] = s.rigid_velocity[b];
        continue;
      }
      v[b] = data[b].momentum / data[b].mass;
    }
    if (s.contact && s.correct_projected_velocities && s.subcycled_body < 0 && n_with_mass > 1)
    {
      // Uintah's first pass: the projected velocities are corrected before the forces act.
      // Nothing is booked: the points' FLIP increments v_new - v leave it out, as Uintah's do.
      resolve_contact(s, data, nodal_stress(s, fields, node), v, n_bodies,
                      unbooked_force.data());
    }
    for (std::size_t b = 0; b < n_bodies; ++b)
    {
      if (data[b].mass <= s.mass_tolerance || s.body_is_rigid[b])
        continue;
      // The contact leader's internal forces act in its own substeps: at the scene's step they
      // would be unstable, and contact needs its velocity only.
      const bool leader = static_cast<int>(b) == s.subcycled_body;
      const Vector3 acceleration =
        leader ? s.gravity : Vector3(data[b].force / data[b].mass + s.gravity);
      v_new[b] = v[b] + dt * acceleration;
    }
    if (s.contact && n_with_mass > 1)
      continue; // resolve_contacts applies the face conditions after the correction
    const bool owned = !s.owns_node || s.owns_node(key);
    for (std::size_t b = 0; b < n_bodies; ++b)
      if (data[b].mass > s.mass_tolerance && !s.body_is_rigid[b])
      {
        const Vector3 trial = v_new[b]; // v^n stays: FLIP sees the stop
        apply_face_conditions(grid, s.faces, key, data[b].mass, v_new[b],
                              owned ? impulse_local : impulse_elsewhere);
        if (change)
          change[b] = stopped_change(grid, s.faces, key, v[b], trial, v_new[b]);
      }
  }
#pragma omp critical
  for (int f = 0; f < 6; ++f)
    result.support_impulse[f] += impulse_local[f];
  }
}

void resolve_contacts(const Grid& grid, const GridUpdateSettings& s, GridFields& fields,
                      GridUpdateResult& result)
{
  const std::size_t n_bodies = fields.n_bodies;
  const long n_nodes = static_cast<long>(grid.n_active());
  result.contact_force.assign(n_bodies, Vector3::Zero());
  result.peak_node_force.assign(n_bodies, 0.0);
  result.contact_moment.assign(n_bodies, Vector3::Zero());
  result.contact_dissipation = 0.0;
  result.n_contact_nodes = 0;
  result.rigid_meeting_node = -1;
  if (!s.contact)
    return;
  double dissipation = 0.0;
  std::size_t n_contact_nodes = 0;
  const std::vector<std::int64_t>& keys = grid.active_keys();
  fields.contact_change.resize(fields.velocity_new.size());
  const bool supports = any_support(s.faces); // update_grid sized fields.support_change
#pragma omp parallel reduction(+ : dissipation, n_contact_nodes)
  {
    std::vector<Vector3> force_local(n_bodies, Vector3::Zero());
    std::vector<double> peak_local(n_bodies, 0.0);
    std::vector<Vector3> moment_local(n_bodies, Vector3::Zero());
    std::vector<Vector3> force_elsewhere(n_bodies, Vector3::Zero()); // another rank's node
    std::array<Vector3, 6> impulse_local, impulse_elsewhere;
    impulse_local.fill(Vector3::Zero());
    impulse_elsewhere.fill(Vector3::Zero());
#pragma omp for schedule(static)
    for (long node = 0; node < n_nodes; ++node)
    {
      const NodeBodyData* data = &fields.data[node * n_bodies];
      Vector3* change = &fields.contact_change[node * n_bodies];
      std::size_t n_with_mass = 0;
      for (std::size_t b = 0; b < n_bodies; ++b)
      {
        n_with_mass += data[b].mass > s.mass_tolerance;
        change[b].setZero();
      }
      if (n_with_mass < 2)
        continue;
      std::size_t rigid_present[2] = {0, 0}, n_rigid = 0;
      for (std::size_t b = 0; b < n_bodies; ++b)
        if (data[b].mass > s.mass_tolerance && s.body_is_rigid[b] && n_rigid++ < 2)
          rigid_present[n_rigid - 1] = b;
      if (n_rigid >= 2)
      {
        if (rigid_bodies_touch(s, data, rigid_present[0], rigid_present[1]))
#pragma omp critical
          if (result.rigid_meeting_node < 0 || keys[node] < result.rigid_meeting_node)
          {
            result.rigid_meeting_node = keys[node];
            result.rigid_meeting_bodies[0] = rigid_present[0];
            result.rigid_meeting_bodies[1] = rigid_present[1];
          }
        continue;
      }
      Vector3* v_new = &fields.velocity_new[node * n_bodies];
      // Sums over owned nodes only, so that ranks sharing a node count it once.
      const bool owned = !s.owns_node || s.owns_node(keys[node]);
      Vector3* force = owned ? force_local.data() : force_elsewhere.data();
      const std::size_t rigid = rigid_present[0];
      const Vector3 rigid_force_before = n_rigid == 1 ? force[rigid] : Vector3::Zero();
      const double removed =
        resolve_contact(s, data, nodal_stress(s, fields, node), v_new, n_bodies, force, change);
      if (n_rigid == 1)
      {
        const Vector3 on_rigid = force[rigid] - rigid_force_before;
        peak_local[rigid] = std::max(peak_local[rigid], on_rigid.norm());
        if (owned)
          moment_local[rigid] += grid.node_position(keys[node]).cross(on_rigid);
      }
      if (owned)
      {
        ++n_contact_nodes;
        dissipation += removed;
      }
      Vector3* held = supports ? &fields.support_change[node * n_bodies] : nullptr;
      for (std::size_t b = 0; b < n_bodies; ++b)
        if (data[b].mass > s.mass_tolerance && !s.body_is_rigid[b])
        {
          const Vector3 trial = v_new[b] - change[b];
          apply_face_conditions(grid, s.faces, keys[node], data[b].mass, v_new[b],
                                owned ? impulse_local : impulse_elsewhere);
          // The face conditions are projections: what is left of the correction after them.
          apply_face_conditions(grid, s.faces, keys[node], change[b]);
          if (held) // the supports' share of the correction
            held[b] = stopped_change(grid, s.faces, keys[node], fields.velocity[node * n_bodies + b],
                                     trial, v_new[b] - change[b]);
        }
    }
#pragma omp critical
    {
      for (std::size_t b = 0; b < n_bodies; ++b)
      {
        result.contact_force[b] += force_local[b];
        result.peak_node_force[b] = std::max(result.peak_node_force[b], peak_local[b]);
        result.contact_moment[b] += moment_local[b];
      }
      for (int f = 0; f < 6; ++f)
        result.support_impulse[f] += impulse_local[f];
    }
  }
  result.contact_dissipation = dissipation;
  result.n_contact_nodes = n_contact_nodes;
}

void velocities_from_momenta(const Grid& grid, const GridUpdateSettings& s, GridFields& fields)
{
  const std::size_t n_bodies = fields.n_bodies;
  const long n_nodes = static_cast<long>(grid.n_active());
#pragma omp parallel for schedule(static)
  for (long node = 0; node < n_nodes; ++node)
  {
    const std::int64_t key = grid.active_keys()[node];
    for (std::size_t b = 0; b < n_bodies; ++b)
    {
      const std::size_t e = node * n_bodies + b;
      const NodeBodyData& d = fields.data[e];
      if (d.mass <= s.mass_tolerance)
      {
        fields.velocity[e].setZero();
        continue;
      }
      if (s.body_is_rigid[b])
      {
        fields.velocity[e] = s.rigid_velocity[b];
        continue;
      }
      fields.velocity[e] = fields.projected_momentum[e] / d.mass;
      apply_face_conditions(grid, s.faces, key, fields.velocity[e]);
    }
  }
}
} // namespace vulnus::mpm
