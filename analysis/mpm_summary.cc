// Builds summary.json from the final MPM state.
#include "analysis/mpm_summary.h"

#include "analysis/penetration_resolution.h"
#include "analysis/wound_metrics.h"
#include "analysis/wound_resolution.h"
#include "mpm/body_builder.h"

#include <algorithm>
#include <cmath>

namespace vulnus::analysis
{
std::string projectile_fate(const mpm::ProjectileExit& exit, const bool through_exit_face,
                            const mpm::ProjectilePenetration& penetration,
                            const double velocity_now, const double stop_speed)
{
  if (exit.recorded && through_exit_face)
    return "left the target through its far side";
  if (exit.recorded)
    return penetration.stopped() ? "stopped in the target, then left it backwards"
                                 : "left the target sideways or backwards";
  if (!penetration.entered())
    return "has not reached the target";
  if (penetration.stopped())
    return velocity_now < -stop_speed ? "stopped in the target, now moving backwards"
                                      : "stopped in the target";
  return "still moving into the target";
}

namespace
{

/// summary.json's condition of a domain face: "fixed (no body reached it)" for a support that
/// gave no impulse and that no deformable body came within a cell of at the start
/// (simulator/scene_warnings.cc warns of it before the run). Not for a hybrid's MPM zone, part
/// of a body whose far field may hold the face.
std::string support_condition(const mpm::Solver& solver, const int face,
                              const mpm::Vector3& impulse)
{
  const mpm::SceneParameters& scene = solver.scene();
  if (scene.axisymmetric && face != 1 && face != 2 && face != 3) // mpm/axisymmetry.h
    return face == 0 ? "axis (v_r = 0)" : "hoop direction (no velocity across the plane)";
  const std::string name = std::string(scene::face_condition_name(scene.domain_faces[face])) +
                           (scene.axisymmetric && face == 1 ? " (the surface r = R)" : "");
  if (scene.domain_faces[face] == mpm::FaceCondition::free || impulse != mpm::Vector3::Zero() ||
      solver.shared_nodes().partner != nullptr)
    return name;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (!solver.body_material(b).is_rigid() &&
        mpm::gap_to_domain_face(scene, scene.bodies[b], face) < scene.cell_size)
      return name;
  return name + " (no body reached it)";
}

/// A wound of fewer than three points has no shape: aspect ratio and axis are null. A face
/// the path does not cross (or an exit the projectile did not make) has no wound: null.
nlohmann::json outline_json(const FaceOutline& o)
{
  if (!o.measured)
    return nlohmann::json();
  return {{"grid_spacing_m", o.grid_spacing},
          {"area_m2", o.area},
          {"equivalent_diameter_m", o.equivalent_diameter},
          {"aspect_ratio", o.aspect_ratio},
          {"major_axis_direction", {o.major_axis[0], o.major_axis[1], o.major_axis[2]}}};
}

nlohmann::json face_json(const FaceWound& w)
{
  if (w.face < 0)
    return nlohmann::json();
  const bool has_shape = w.n_points >= 3;
  return {{"face", box_face_name(w.face)},
          {"equivalent_diameter_m", w.equivalent_diameter},
          {"aspect_ratio", has_shape ? nlohmann::json(w.aspect_ratio) : nlohmann::json()},
          {"major_axis_direction",
           has_shape ? nlohmann::json{w.major_axis[0], w.major_axis[1], w.major_axis[2]}
                     : nlohmann::json()},
          {"failed_points", w.n_points},
          {"area_m2", w.area},
          {"outline", outline_json(w.outline)}};
}
/// How deep the projectile went: its nose below the target's entrance plane (the plane of the
/// target's nearest points at the start), the deepest it reached and when, whether it stopped
/// (or turned back) inside, and the velocity-depth curve sampled every quarter cell of depth.
nlohmann::json penetration_json(const mpm::ProjectilePenetration& p)
{
  nlohmann::json curve = {{"time_s", nlohmann::json::array()},
                          {"depth_m", nlohmann::json::array()},
                          {"velocity_m_s", nlohmann::json::array()}};
  for (const mpm::PenetrationSample& s : p.curve())
  {
    curve["time_s"].push_back(s.time);
    curve["depth_m"].push_back(s.depth);
    curve["velocity_m_s"].push_back(s.speed);
  }
  const bool stopped = p.stopped();
  return {{"depth_m", p.latest().depth},
          {"max_depth_m", p.max_depth()},
          {"max_depth_time_s", p.max_depth_time()},
          {"stopped", stopped},
          {"stop_time_s", stopped ? nlohmann::json(p.stop().time) : nlohmann::json()},
          {"stop_depth_m", stopped ? nlohmann::json(p.stop().depth) : nlohmann::json()},
          {"stop_velocity_m_s", stopped ? nlohmann::json(p.stop().speed) : nlohmann::json()},
          {"curve", curve}};
}
} // namespace

double accounted_energy(const mpm::Solver& solver, const mpm::SceneDiagnostics& d)
{
  return d.kinetic_energy + d.strain_energy + d.potential_energy + d.dissipated_energy +
         solver.contact_dissipation() + solver.support_dissipation() + solver.removed_energy() -
         solver.prescribed_work();
}

double mpm_balance_error(const mpm::Solver& solver, const mpm::SceneDiagnostics& d)
{
  const double initial = solver.initial_energy();
  const double given = initial + std::abs(solver.prescribed_work());
  return given > 0 ? (accounted_energy(solver, d) - initial) / given : 0.0;
}

MomentumAudit mpm_momentum_audit(const mpm::Solver& solver, const mpm::SceneDiagnostics& d,
                                 const std::array<mpm::Vector3, 6>& supports)
{
  MomentumAudit audit;
  audit.initial = solver.initial_momentum();
  audit.now = d.momentum;
  audit.removed = solver.removed_momentum();
  audit.external = solver.external_impulse();
  audit.added = solver.added_momentum();
  for (const mpm::Vector3& j : supports)
    audit.add_support(j);
  return audit;
}

nlohmann::json mpm_summary(const mpm::Solver& solver, const RunTotals& totals,
                           const WoundSample& sample, const mpm::SceneDiagnostics& d,
                           const std::array<mpm::Vector3, 6>& supports)
{
  const mpm::Vector3 axis = solver.flight_direction();
  const int projectile = solver.projectile();
  const WoundMetrics wound = wound_metrics_of(sample, solver, totals.wound_face_layer,
                                              totals.wound_outline_grid);

  nlohmann::json j;
  j["completed"] = totals.completed;
  if (!totals.completed)
    j["error"] = totals.error;
  j["particles"] = sample.n_points;
  if (!solver.mirror_planes().empty())
  {
    // The wound figures are the whole scene's (analysis::complete_by_mirrors).
    nlohmann::json faces = nlohmann::json::array();
    for (const mpm::SymmetryPlane& plane : solver.mirror_planes())
      faces.push_back(box_face_name(plane.face));
    j["symmetry"] = {{"faces", faces},
                     {"modelled_share", mpm::modelled_share(solver.mirror_planes())},
                     {"figures", "energies, masses, momenta, forces, impulses and point counts "
                                 "of the modelled part; wound, cavity and penetration figures "
                                 "of the whole scene"}};
  }
  j["mpi"] = {{"ranks", solver.rank_group().size()}, {"bytes_sent", totals.mpi_bytes_sent}};
  j["fe_cells"] = 0;
  j["steps"] = solver.step_count();
  j["time_s"] = solver.time();
  j["wall_seconds"] = totals.wall_seconds;
  j["particle_steps_per_second"] =
    totals.wall_seconds > 0 ? double(sample.n_points) * solver.step_count() / totals.wall_seconds : 0.0;
  j["failed"] = {{"matrix", wound.counts[1]}, {"fiber", wound.counts[2]}, {"total", wound.counts[3]}};
  j["failed_volume_m3"] = {{"matrix", wound.volumes[1]}, {"fiber", wound.volumes[2]}, {"total", wound.volumes[3]}};
  j["debris"] = {{"count", wound.debris_count}, {"volume_m3", wound.debris_volume}};
  j["entrance_wound"] = face_json(wound.entrance);
  j["exit_wound"] = face_json(wound.exit);
  j["wound_face_layer_m"] = wound.face_layer;
  bool fibred_target = false;
  for (std::size_t b = 0; b < solver.points().n_bodies(); ++b)
    if (static_cast<int>(b) != projectile && solver.body_material(b).uses_fibers())
      fibred_target = true;
  nlohmann::json figures = nlohmann::json::array(), unresolved = nlohmann::json::array();
  for (const FigureResolution& r : resolve_wound_figures(wound, solver.scene().cell_size, fibred_target))
  {
    figures.push_back({{"figure", r.figure}, {"cells_across", r.cells_across},
                       {"resolved", r.resolved},
                       {"reason", r.resolved ? nlohmann::json() : nlohmann::json(r.reason)}});
    if (!r.resolved)
      unresolved.push_back(r.figure);
  }
  j["wound_resolution"] = {{"cells_needed", cells_needed}, {"figures", figures},
                           {"unresolved", unresolved}};
  j["tract"] = {{"depth_m", wound.tract_depth},
                {"area_m2", wound.tract_area},
                {"debris_area_m2", wound.debris_tract_area},
                {"path_length_m", wound.path.length()},
                {"direction", {axis[0], axis[1], axis[2]}}};

  nlohmann::json bullet = nlohmann::json::object();
  if (projectile >= 0)
  {
    const mpm::BodySummary& b = d.bodies[projectile];
    // At the exit when the projectile left the target (the run may go on after it).
    const mpm::ProjectileExit& exit = solver.projectile_exit();
    const double speed = exit.recorded ? exit.velocity.dot(axis) : b.velocity.dot(axis);
    const double kinetic = exit.recorded ? exit.kinetic_energy : b.kinetic_energy;
    bullet["initial_velocity_m_s"] = totals.projectile_initial_speed;
    bullet["exited"] = exit.recorded;
    // Exit fields only for an exit that happened (null otherwise); the speed now always.
    bullet["exit_time_s"] = exit.recorded ? nlohmann::json(exit.time) : nlohmann::json();
    bullet["exit_velocity_m_s"] = exit.recorded ? nlohmann::json(speed) : nlohmann::json();
    bullet["velocity_now_m_s"] = b.velocity.dot(axis);
    bullet["fate"] = projectile_fate(exit, left_through_exit_face(sample, solver),
                                     solver.penetration(), b.velocity.dot(axis),
                                     solver.scene().projectile_stop_speed);
    bullet["kinetic_energy_lost_J"] = totals.projectile_initial_kinetic_energy - kinetic;
    bullet["max_von_mises_over_yield"] = solver.peak_von_mises_over_yield()[projectile];
    bullet["position_m"] = {b.centroid[0], b.centroid[1], b.centroid[2]};
    bullet["rigid"] = solver.body_material(projectile).is_rigid();
    const mpm::RigidHold& hold = solver.projectile_hold();
    const mpm::RigidHoldRecord& held = hold.record();
    if (held.considered())
      bullet["rigid_hold"] = {
        {"held_now", held.held},
        {"held_from_start", held.held || held.release_step >= 0},
        {"release_step", held.release_step >= 0 ? nlohmann::json(held.release_step) : nlohmann::json()},
        {"release_time_s", held.release_step >= 0 ? nlohmann::json(held.release_time) : nlohmann::json()},
        {"reason", held.reason},
        {"impact_pressure_Pa", held.impact_pressure},
        {"peak_contact_pressure_Pa", held.peak_pressure},
        {"peak_contact_pressure_time_s", held.peak_pressure_time},
        {"contact_pressure_limit_Pa", hold.pressure_limit()},
        {"rotation_drift_m", held.rotation_drift},
        {"rotation_drift_limit_m", hold.drift_limit()}};
    // A free rigid projectile only translates: the rotation its contact's moment would give.
    if (const mpm::NeglectedRotation& rotation = solver.projectile_rotation(); rotation.active())
      bullet["rotation_neglected"] = {
        {"angle_rad", rotation.angle()},
        {"drift_m", rotation.drift()},
        {"drift_limit_m", rotation.drift_limit()},
        {"exceeded_step", rotation.exceeded_step() >= 0 ? nlohmann::json(rotation.exceeded_step())
                                                        : nlohmann::json()}};
    j["penetration"] = penetration_json(solver.penetration());
    const PenetrationResolution resolution =
      resolve_penetration(solver.scene().bodies[projectile], solver.scene().cell_size);
    j["penetration"]["resolution"] = {
      {"projectile_width_m", resolution.width_m}, {"cells_across", resolution.cells_across},
      {"cells_needed", projectile_cells_needed}, {"resolved", resolution.resolved},
      {"reason", resolution.resolved ? nlohmann::json() : nlohmann::json(resolution.reason)}};
    // Fastest point of the other bodies over the run, against the projectile's initial speed.
    double fastest = 0.0;
    for (std::size_t other = 0; other < solver.peak_point_speeds().size(); ++other)
      if (static_cast<int>(other) != projectile)
        fastest = std::max(fastest, solver.peak_point_speeds()[other]);
    j["max_target_speed_m_s"] = fastest;
    j["max_target_speed_over_initial"] =
      totals.projectile_initial_speed > 0 ? fastest / totals.projectile_initial_speed : 0.0;
  }
  j["bullet"] = bullet;

  // The target (every body but the projectile) and what the supports gave it.
  double target_kinetic = 0.0;
  mpm::Vector3 target_momentum = mpm::Vector3::Zero();
  for (std::size_t b = 0; b < d.bodies.size(); ++b)
    if (static_cast<int>(b) != projectile)
    {
      target_kinetic += d.bodies[b].kinetic_energy;
      target_momentum += d.bodies[b].mass * d.bodies[b].velocity;
    }
  j["target"] = {{"kinetic_energy_J", target_kinetic},
                 {"momentum_kg_m_s", {target_momentum[0], target_momentum[1], target_momentum[2]}}};
  for (int f = 0; f < 6; ++f)
    j["supports"][box_face_name(f)] = {{"condition", support_condition(solver, f, supports[f])},
                                    {"impulse_N_s", {supports[f][0], supports[f][1], supports[f][2]}}};

  const double initial = solver.initial_energy();
  j["energy"] = {{"initial_J", initial},
                 {"kinetic_J", d.kinetic_energy},
                 {"strain_J", d.strain_energy},
                 {"potential_J", d.potential_energy},
                 {"dissipated_J", d.dissipated_energy + solver.contact_dissipation() +
                                    solver.support_dissipation()},
                 {"dissipated_material_J", d.dissipated_energy},
                 {"dissipated_contact_J", solver.contact_dissipation()},
                 {"dissipated_supports_J", solver.support_dissipation()},
                 {"outflow_J", solver.removed_energy()},
                 {"work_prescribed_J", solver.prescribed_work()},
                 {"balance_error", mpm_balance_error(solver, d)}};
  j["removed_points"] = solver.removed_points();
  j["split_points"] = solver.split_points();
  j["momentum_audit"] = momentum_audit_json(mpm_momentum_audit(solver, d, supports));
  j["warnings"] = totals.warnings;
  return j;
}
} // namespace vulnus::analysis
