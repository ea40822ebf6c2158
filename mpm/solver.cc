// Orchestration of the MPM time step.
#include "mpm/solver.h"

#include "materials/material_registry.h"
#include "mpm/axisymmetry.h"
#include "mpm/body_builder.h"
#include "mpm/nonlocal_failure.h"
#include "materials/material_parameters.h"
#include "mpm/projectile_gather.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <omp.h>
#include <sstream>

namespace vulnus::mpm
{
Solver::Solver(const SceneParameters& deck, const MPI_Comm communicator)
  : parameters(deck.axisymmetric ? plane_of_revolution(deck) : deck), ranks(communicator),
    grid(parameters.domain_min, parameters.domain_max, parameters.cell_size, parameters.axisymmetric,
         parameters.grading)
{
  const SceneParameters& scene = parameters;
  if (scene.axisymmetric && ranks.distributed())
    throw std::invalid_argument("Grid/Dimension = axisymmetric runs on one MPI rank; use threads");
  if (grid.graded() && (scene.shape_function != ShapeFunction::linear ||
                        scene.cell_volume_from_grid_flux || ranks.distributed()))
    throw std::invalid_argument("a graded grid (Grid/Grading) takes linear shape functions, no "
                                "grid flux averaging and one MPI rank");
  planes_of_symmetry = symmetry_planes(deck);
  if (!planes_of_symmetry.empty() &&
      (scene.axisymmetric || scene.shape_function != ShapeFunction::linear))
    throw std::invalid_argument("a symmetry face (Grid/Boundary conditions) takes a 3D grid and "
                                "linear shape functions, whose points reach no node beyond it");
  if (!planes_of_symmetry.empty() && (scene.velocity_transfer == VelocityTransfer::xpic ||
                                      scene.velocity_transfer == VelocityTransfer::fmpm))
    throw std::invalid_argument("a symmetry face (Grid/Boundary conditions) does not take XPIC or "
                                "FMPM, whose grid series would reach beyond it");
  plan_point_splitting();
  if (scene.axisymmetric && revolved(scene.gravity) != scene.gravity)
    throw std::invalid_argument("an axisymmetric scene's gravity must be along the axis y");
  const std::size_t n_bodies = scene.bodies.size();
  if (n_bodies == 0)
    throw std::invalid_argument("Scene/Bodies: no body; name at least one");

  // One material object per named material, shared by the bodies that use it.
  std::vector<std::string> material_names;
  for (const NamedMaterial& m : scene.materials)
  {
    material_names.push_back(m.name);
    owned_materials.push_back(materials::create_material(m.parameters));
  }
  for (const BodyParameters& body : scene.bodies)
  {
    const auto it = std::find(material_names.begin(), material_names.end(), body.material);
    if (it == material_names.end())
      throw std::invalid_argument("Body " + body.name + "/Material: unknown material '" +
                                  body.material + "'; use one of the names in Scene/Materials");
    materials_of_body.push_back(owned_materials[it - material_names.begin()].get());
  }

  nonlocal_failure = uses_nonlocal_failure(materials_of_body);
  if (nonlocal_failure)
    failure_limit_flags = failure_limit_flags_for(materials_of_body);
  for (std::size_t b = 0; b < n_bodies; ++b)
    if (const materials::FailureParameters* c = materials_of_body[b]->failure_criterion())
      for (const ParameterProblem& p : check_regularization(*c, scene.cell_size, ranks.size()))
        throw std::invalid_argument("material '" + scene.bodies[b].material +
                                    "', failure regularization length: " + describe(p));

  // A distributed run cuts the slabs from the points' positions first, then each rank builds
  // only the points of its own slab.
  plan_slabs();
  const std::vector<char> plastic_history = bodies_with_plastic_history();
  if (ranks.distributed())
    build_bodies(scene, grid, particles, plastic_history, [this](const Vector3& x)
                 { return partition.rank_of_position(grid, x) == ranks.rank(); });
  else
    build_bodies(scene, grid, particles, plastic_history);

  transfer.shape = scene.shape_function;
  for (const BodyParameters& body : scene.bodies)
    transfer.half_size_cells.push_back(0.5 / body.particles_per_cell);
  // Contact off: the bodies share one velocity field, which is the no-slip correction (the
  // centre-of-mass velocity at every node several bodies reach).
  contact_active = n_bodies > 1 && !scene.contact.ignore_other_bodies;
  const bool affine = scene.velocity_transfer == VelocityTransfer::apic ||
                      scene.velocity_transfer == VelocityTransfer::relaxed_apic;
  const double friction = scene.contact.enabled ? scene.contact.friction_coefficient : -1.0;
  transfer.contact_normals = contact_active && friction >= 0.0;

  body_mass.assign(n_bodies, 0.0);
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
      body_mass[b] += particles.mass[p];
  ranks.sum(body_mass.data(), static_cast<int>(n_bodies));

  grid_settings.faces = scene.domain_faces;
  grid_settings.gravity = scene.gravity;
  grid_settings.contact = contact_active;
  grid_settings.friction_coefficient = friction;
  grid_settings.contact_distance = scene.contact.proximity_distance * scene.cell_size;
  grid_settings.contact_band = 0.05 * scene.cell_size;
  grid_settings.hold_compressed_surfaces = contact_active && scene.contact.hold_compressed_surfaces;
  grid_settings.correct_projected_velocities = contact_active && scene.contact.two_passes;
  // Any node with mass gets a velocity: p / m is a weighted mean of point velocities even
  // where m is tiny, and zeroing light nodes breaks exact translation.
  grid_settings.mass_tolerance = 0.0;
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    grid_settings.body_is_rigid.push_back(materials_of_body[b]->is_rigid());
    grid_settings.rigid_velocity.push_back(scene.bodies[b].initial_velocity);
  }
  transfer.affine = affine;
  kinematics.affine = transfer.affine;
  kinematics.flip_fraction = scene.velocity_transfer == VelocityTransfer::flip ? 1.0 : 0.0;
  kinematics.deformation_update = scene.deformation_update;
  kinematics.track_domains = scene.point_split_edge_cells > 0.0;
  kinematics.body_is_rigid = grid_settings.body_is_rigid;
  kinematics.rigid_velocity = grid_settings.rigid_velocity;

  stress_settings.cell_size = scene.cell_size;
  stress_settings.graded_grid = grid.graded() ? &grid : nullptr;
  stress_settings.viscosity = {scene.artificial_viscosity_linear,
                               scene.artificial_viscosity_quadratic};
  stress_settings.body_material = materials_of_body;
  for (const BodyParameters& body : scene.bodies)
    stress_settings.body_density.push_back(body.density);
  peak_yield_ratio.assign(n_bodies, 0.0);
  peak_point_speed.assign(n_bodies, 0.0);

  for (std::size_t b = 0; b < n_bodies; ++b)
    if (scene.bodies[b].is_projectile)
      projectile_body = static_cast<int>(b);
  if (projectile_body >= 0)
  {
    const Vector3 v0 = scene.bodies[projectile_body].initial_velocity;
    flight_axis = v0.norm() > 0 ? Vector3(v0.normalized()) : Vector3::UnitY();
    measure_path_through_target(scene);
    penetration_record = ProjectilePenetration(0.25 * scene.cell_size);
  }

  // Initial stresses and wave speeds (non-zero when a body starts deformed is not supported:
  // F = I, so this gives the small-strain moduli for the first CFL step).
  stress_settings.time_step = 0.0;
  update_stresses(stress_settings, volumetric_rate_or_null(), particles, stress_result);
  begin_rigid_hold();
  plan_exact_rigid_surfaces();
  begin_rotation_estimate(); // with a rigid material's exact mass
  plan_projectile_subcycle();
  sort_points();
  const SceneDiagnostics d = diagnostics();
  energy_at_start = d.kinetic_energy + d.strain_energy + d.potential_energy;
  momentum_at_start = d.momentum;
  check_state();
}

bool Solver::projectile_is_far_stiffer() const
{
  const std::vector<double> impedance = body_impedances();
  for (std::size_t b = 0; b < impedance.size(); ++b)
    if (static_cast<int>(b) != projectile_body && !grid_settings.body_is_rigid[b] &&
        impedance[projectile_body] < minimum_impedance_ratio * impedance[b])
      return false;
  return true;
}

void Solver::plan_projectile_subcycle()
{
  const int b = projectile_body;
  if (!parameters.subcycle_projectile || b < 0 || grid_settings.body_is_rigid[b] ||
      particles.n_bodies() < 2 || !projectile_is_far_stiffer())
    return;
  SubcycleStages stages;
  stages.transfer = transfer;
  stages.transfer.half_size_cells = {transfer.half_size_cells[b]};
  stages.transfer.contact_normals = false;
  stages.grid_update = grid_settings;
  stages.grid_update.body_is_rigid = {0};
  stages.grid_update.rigid_velocity = {Vector3::Zero()};
  stages.kinematics = kinematics;
  stages.kinematics.body_is_rigid = {0};
  stages.kinematics.rigid_velocity = {Vector3::Zero()};
  stages.stress = stress_settings;
  stages.stress.body_material = {materials_of_body[b]};
  stages.stress.body_density = {parameters.bodies[b].density};
  stages.musl = parameters.update_scheme == UpdateScheme::musl;
  if (!planes_of_symmetry.empty())
    throw std::invalid_argument("a symmetry face (Grid/Boundary conditions) does not take a "
                                "subcycled projectile, whose own scatter it does not mirror");
  subcycle = std::make_unique<ProjectileSubcycle>(grid, stages);
  grid_settings.subcycled_body = b;
  kinematics.body_advanced_elsewhere.assign(particles.n_bodies(), 0);
  kinematics.body_advanced_elsewhere[b] = 1;
  stress_settings.body_advanced_elsewhere = kinematics.body_advanced_elsewhere;
}

void Solver::advance_projectile_substeps(const double dt)
{
  const int b = projectile_body;
  const double flip = kinematics.body_flip_fraction.empty() ? kinematics.flip_fraction
                                                            : kinematics.body_flip_fraction[b];
  Particles projectile = particles.copy_of_body(b);
  std::vector<Vector3> force = projectile_contact_force;
  std::size_t first_of_mine = 0;
  if (ranks.distributed())
  {
    GatheredProjectile all = gather_on_every_rank(ranks, projectile, force);
    projectile = std::move(all.points);
    force = std::move(all.force);
    first_of_mine = all.first_of_mine;
  }
  const std::size_t n_mine = particles.end_of(b) - particles.begin_of(b);
  const SubcycleResult result =
    subcycle->advance(projectile, force, dt, n_projectile_substeps, flip);
  particles.write_back_body(
    b, ranks.distributed() ? projectile.copy_of_range(first_of_mine, first_of_mine + n_mine)
                           : projectile);
  peak_yield_ratio[b] = std::max(peak_yield_ratio[b], result.max_von_mises_over_yield);
  if (ranks.rank() == 0) // every rank advanced the same points; impulses are summed later
    for (int f = 0; f < 6; ++f)
      support_impulse_here[f] +=
        parameters.axisymmetric ? revolved(result.support_impulse[f]) : result.support_impulse[f];
  accumulated_contact_dissipation -= result.contact_work; // a total on every rank
  accumulated_support_dissipation += result.support_loss; // likewise
  const long failed = result.failed_point - static_cast<long>(first_of_mine);
  if (failed >= 0 && failed < static_cast<long>(n_mine) && stress_result.failed_point < 0)
  {
    stress_result.failed_point = static_cast<long>(particles.begin_of(b)) + failed;
    stress_result.failure_message = result.failure_message;
  }
}

void Solver::relax_projectile_velocities(const double dt, const std::vector<double>& signal_speed)
{
  kinematics.body_flip_fraction.clear();
  const int b = projectile_body;
  if (parameters.projectile_velocity_relaxation <= 0.0 || b < 0 ||
      grid_settings.body_is_rigid[b] || !(signal_speed[b] > 0.0))
    return;
  // Relaxed at the projectile's own Courant time: its ringing is damped within a few of its
  // wave transits of a cell, at a rate fixed in time, while the target keeps its transfer.
  kinematics.body_flip_fraction.assign(particles.n_bodies(), kinematics.flip_fraction);
  const double courant_time = parameters.cell_size / signal_speed[b];
  kinematics.body_flip_fraction[b] =
    kinematics.flip_fraction *
    std::exp(-dt / (parameters.projectile_velocity_relaxation * courant_time));
}

double Solver::stable_time_step() const
{
  return step_limit(nullptr);
}

double Solver::step_limit(std::vector<double>* fastest_point_of_body,
                          std::vector<double>* signal_speed_of_body) const
{
  double fastest = 0.0;
  if (fastest_point_of_body)
    fastest_point_of_body->assign(particles.n_bodies(), 0.0);
  if (signal_speed_of_body)
    signal_speed_of_body->assign(particles.n_bodies(), 0.0);
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    const long begin = particles.begin_of(b), end = particles.end_of(b);
    if (grid_settings.body_is_rigid[b])
    {
      fastest = std::max(fastest, grid_settings.rigid_velocity[b].norm());
      if (fastest_point_of_body)
        (*fastest_point_of_body)[b] = grid_settings.rigid_velocity[b].norm();
      continue;
    }
    double body_fastest = 0.0, body_speed = 0.0;
#pragma omp parallel for schedule(static) reduction(max : body_fastest, body_speed)
    for (long p = begin; p < end; ++p)
    {
      const double speed = particles.velocity[p].norm();
      body_fastest = std::max(body_fastest, particles.wave_speed[p] + speed);
      body_speed = std::max(body_speed, speed);
    }
    // A subcycled projectile limits the scene's step only by crossing cells.
    fastest = std::max(fastest, subcycle && static_cast<int>(b) == projectile_body ? body_speed
                                                                                 : body_fastest);
    if (fastest_point_of_body)
      (*fastest_point_of_body)[b] = body_speed;
    if (signal_speed_of_body)
      (*signal_speed_of_body)[b] = body_fastest;
  }
  fastest = ranks.max(fastest);
  if (fastest_point_of_body)
    ranks.max(fastest_point_of_body->data(), static_cast<int>(fastest_point_of_body->size()));
  if (signal_speed_of_body)
    ranks.max(signal_speed_of_body->data(), static_cast<int>(signal_speed_of_body->size()));
  const double limit = fastest > 0.0 ? parameters.cfl * parameters.cell_size / fastest
                                     : parameters.max_time_step;
  return std::min(limit, parameters.max_time_step);
}

void Solver::advance(const double cap)
{
  double clock = omp_get_wtime();
  auto lap = [&clock](double& phase) {
    const double now = omp_get_wtime();
    phase += now - clock;
    clock = now;
  };
  std::vector<double> fastest_point, signal_speed;
  const double stable = step_limit(&fastest_point, &signal_speed);
  for (std::size_t b = 0; b < fastest_point.size(); ++b)
    peak_point_speed[b] = std::max(peak_point_speed[b], fastest_point[b]);
  if (!(stable >= parameters.min_time_step))
  {
    std::ostringstream problem;
    problem << "time step collapsed at step " << n_steps << ", t = " << current_time
            << " s: CFL step " << stable << " s is below {min_time_step} "
            << parameters.min_time_step << " s";
    throw BlowUp(RunFailure{problem.str(),
                            "a point moving or vibrating far too fast (a CFL number too high, a "
                            "bulk modulus too large for the cell size, or an unstable contact)",
                            "a smaller {cfl} (or {min_time_step}, when it lies above the scene's "
                            "stable step), or check the bulk modulus and the contact settings"});
  }
  const double to_reach = std::min(parameters.end_time - current_time, cap);
  time_step = to_reach <= stable || std::isinf(cap)
                ? std::min(stable, to_reach)
                : to_reach / std::ceil(to_reach / stable * (1.0 - 1e-12));
  if (time_step <= 0.0)
    return;
  const double dt = time_step;
  if (!shared.partner && (parameters.velocity_transfer == VelocityTransfer::relaxed_apic ||
                          parameters.velocity_transfer == VelocityTransfer::relaxed_pic))
  {
    // The FLIP part decays at a rate fixed in time, so the damping of FLIP's noise (and the
    // drag that repeated damping of a contact layer adds) does not grow with the step count.
    const double courant_time = stable / parameters.cfl;
    kinematics.flip_fraction = std::exp(-dt / (parameters.velocity_relaxation * courant_time));
  }
  relax_projectile_velocities(dt, signal_speed);
  if (subcycle)
  {
    const double cfl =
      parameters.projectile_cfl > 0.0 ? parameters.projectile_cfl : parameters.cfl;
    const double own_step = cfl * parameters.cell_size / signal_speed[projectile_body];
    n_projectile_substeps = std::max(1, static_cast<int>(std::ceil(dt / own_step * (1.0 - 1e-12))));
  }
  lap(timings.time_step);

  const bool grid_flux = parameters.cell_volume_averaging && parameters.cell_volume_from_grid_flux;
  auto flux_paired = [&](const std::size_t b)
  { return grid_flux && !grid_settings.body_is_rigid[b] && !kinematics.skips(b); };
  mark_active_nodes(particles, transfer, grid, grid_flux);
  n_active_last_step = grid.n_active();
  if (grid_flux)
  {
    volume_averaging.clear_pair(particles.size());
    for (std::size_t b = 0; b < particles.n_bodies(); ++b)
      if (flux_paired(b))
        prepare_grid_flux_pair(grid, long(particles.begin_of(b)), long(particles.end_of(b)),
                               particles, volume_averaging);
  }
  const GridFluxPair pair{volume_averaging.paired_stress.data(), volume_averaging.cell.data()};
  particles_to_grid(particles, grid, transfer, buffers, fields, nullptr,
                    grid_flux ? &pair : nullptr);
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
    if (flux_paired(b))
      unpair_cells_without_mass(grid, transfer, b, long(particles.begin_of(b)),
                                long(particles.end_of(b)), particles, fields, volume_averaging);
  if (grid_settings.hold_compressed_surfaces)
    scatter_nodal_stress(particles, grid, transfer, buffers, fields);
  sum_node_data_with_neighbours();
  lap(timings.particle_to_grid);

  grid_settings.time_step = dt;
  mirror_nodal_sums(grid, planes_of_symmetry, grid_settings, kinematics, fields,
                    support_impulse_here);
  update_rigid_surfaces();
  update_grid(grid, grid_settings, fields, grid_result);
  lap(timings.grid_update);
  if (subcycle)
  {
    const std::size_t n_bodies = fields.n_bodies;
    projectile_trial_velocity.resize(grid.n_active());
    for (std::size_t node = 0; node < grid.n_active(); ++node)
      projectile_trial_velocity[node] = fields.velocity_new[node * n_bodies + projectile_body];
  }
  resolve_contacts(grid, grid_settings, fields, grid_result);
  if (const RunFailure failure = ranks.first_failure(rigid_meeting_problem(dt)); !failure.empty())
    throw BlowUp(failure);
  reduce_contact_result();
  if (parameters.axisymmetric)
    revolve_step_results();
  const Vector3 held_velocity =
    rigid_hold.record().held ? grid_settings.rigid_velocity[projectile_body] : Vector3::Zero();
  accumulated_contact_dissipation += grid_result.contact_dissipation;
  for (int f = 0; f < 6; ++f)
    support_impulse_here[f] += grid_result.support_impulse[f];
  if (subcycle)
    projectile_contact_force = contact_force_on_points(grid, transfer, fields,
                                                       projectile_trial_velocity, particles,
                                                       projectile_body, dt);
  lap(timings.contact);
  if (shared.partner)
  {
    exchange_shared_nodes(dt);
    lap(timings.coupling);
  }

  kinematics.time_step = dt;
  if (parameters.velocity_transfer == VelocityTransfer::xpic ||
      parameters.velocity_transfer == VelocityTransfer::fmpm)
    compute_xpic_correction();
  const bool musl = parameters.update_scheme == UpdateScheme::musl;
  const bool supports = any_support(grid_settings.faces);
  const CorrectionLoss loss =
    update_point_kinematics(grid, transfer, kinematics, fields, particles,
                            musl ? &buffers : nullptr, grid_settings.contact, supports);
  if (grid_settings.contact || supports)
  {
    double losses[2] = {loss.contact, loss.supports};
    if (ranks.distributed())
      ranks.sum(losses, 2);
    accumulated_contact_dissipation += losses[0];
    accumulated_support_dissipation += losses[1];
  }
  if (musl)
  {
    sum_projected_momenta_with_neighbours();
    velocities_from_momenta(grid, grid_settings, fields);
    if (shared.partner)
      impose_shared_velocities(fields.velocity, true);
  }
  if (nonlocal_failure)
  {
    failure_limit_flags.passed.resize(particles.size());
  }
  volume_averaging.from_grid_flux = parameters.cell_volume_from_grid_flux;
  update_deformation_gradients_and_positions(grid, transfer, kinematics, fields,
                                             musl ? fields.velocity : fields.velocity_new,
                                             particles, volumetric_rate_or_null(),
                                             nonlocal_failure ? &failure_limit_flags : nullptr,
                                             parameters.cell_volume_averaging ? &volume_averaging
                                                                              : nullptr);
  lap(timings.grid_to_particle);

  stress_settings.time_step = dt;
  if (nonlocal_failure)
  {
    decide_nonlocal_failures(materials_of_body, particles, nonlocal_cache, &failure_limit_flags);
    lap(timings.nonlocal_failure);
  }
  update_stresses(stress_settings, volumetric_rate_or_null(), particles, stress_result);
  if (subcycle)
  {
    lap(timings.stress_update);
    advance_projectile_substeps(dt);
    lap(timings.projectile_substeps);
  }
  std::vector<double> yield_ratio = stress_result.max_von_mises_over_yield;
  ranks.max(yield_ratio.data(), static_cast<int>(yield_ratio.size()));
  for (std::size_t b = 0; b < peak_yield_ratio.size(); ++b)
    peak_yield_ratio[b] = std::max(peak_yield_ratio[b], yield_ratio[b]);

  estimate_projectile_rotation(dt);
  // Free rigid bodies respond to the contact force (translation only); a prescribed motion
  // is held against it from outside, and gravity acts on the deformable bodies, the
  // projectile held rigid while elastic among them.
  const int held = rigid_hold.record().held ? projectile_body : -1;
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    if (!grid_settings.body_is_rigid[b] || static_cast<int>(b) == held)
      accumulated_external_impulse += dt * body_mass[b] * parameters.gravity;
    else if (parameters.bodies[b].rigid_motion != RigidMotion::free)
    {
      accumulated_external_impulse -= dt * grid_result.contact_force[b];
      accumulated_prescribed_work -= dt * grid_result.contact_force[b].dot(grid_settings.rigid_velocity[b]);
    }
  }
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
    if (grid_settings.body_is_rigid[b] && parameters.bodies[b].rigid_motion == RigidMotion::free)
    {
      if (body_mass[b] > 0.0)
        grid_settings.rigid_velocity[b] += dt * grid_result.contact_force[b] / body_mass[b];
      // A body across a mirror plane moves along it: the plane takes the force across it.
      for (const SymmetryPlane& plane : planes_of_symmetry)
        if (crosses(parameters.bodies[b], plane))
        {
          if (ranks.rank() == 0)
            support_impulse_here[plane.face][plane.axis] -=
              dt * grid_result.contact_force[b][plane.axis];
          grid_settings.rigid_velocity[b][plane.axis] = 0.0;
        }
      if (static_cast<int>(b) == held)
        grid_settings.rigid_velocity[b] += dt * parameters.gravity;
      kinematics.rigid_velocity[b] = grid_settings.rigid_velocity[b];
      for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
        particles.velocity[p] = grid_settings.rigid_velocity[b];
    }
  if (rigid_hold.record().held && check_rigid_hold(dt, held_velocity))
    make_projectile_deformable();
  lap(timings.stress_update);

  current_time += dt;
  ++n_steps;
  std::string material_problem;
  if (stress_result.failed_point >= 0)
    material_problem = "material update failed at step " + std::to_string(n_steps) + ", t = " +
                       std::to_string(current_time) + " s, " +
                       describe_point(stress_result.failed_point) + ": " +
                       stress_result.failure_message;
  material_problem = ranks.first_message(material_problem);
  if (!material_problem.empty())
    throw BlowUp(material_problem);
  if (const RunFailure failure = ranks.first_failure(rigid_face_problem()); !failure.empty())
    throw BlowUp(failure);
  record_projectile_exit();
  record_penetration();
  if (parameters.remove_points_leaving_grid)
    remove_points_outside_grid();
  check_state();
  if (splitting.longest_edge > 0.0)
    split_stretched_points();
  if (parameters.sort_interval > 0 && n_steps % parameters.sort_interval == 0)
  {
    rebalance_slabs(); // re-cuts the slabs and migrates
    sort_points();
  }
  else
    migrate_points(false);
  lap(timings.checks_and_sorting);
  if (parameters.cell_volume_averaging)
  {
    // Where the points now sit, all of a cell's on this rank: the next forces' pressures.
    for (std::size_t b = 0; b < particles.n_bodies(); ++b)
      if (!grid_settings.body_is_rigid[b] && !kinematics.skips(b))
        average_cell_pressures(grid, long(particles.begin_of(b)), long(particles.end_of(b)),
                               particles, volume_averaging);
    lap(timings.stress_update);
  }
}

bool Solver::finished() const
{
  if (current_time >= parameters.end_time * (1.0 - 1e-12))
    return true;
  if (parameters.stop_when_projectile_stops && penetration_record.stopped())
    return true;
  return stops_at_projectile_exit() && exit_record.recorded;
}

bool Solver::stops_at_projectile_exit() const
{
  return parameters.stop_when_projectile_exits && projectile_body >= 0 && particles.n_bodies() > 1;
}

double Solver::projectile_tail() const
{
  double tail = std::numeric_limits<double>::max();
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
    tail = std::min(tail, particles.position[p].dot(flight_axis));
  return ranks.min(tail);
}

double Solver::expected_end_time() const
{
  const double end = parameters.end_time;
  if (!stops_at_projectile_exit())
    return end;
  const double tail = projectile_tail();
  double momentum = 0.0, mass = 0.0;
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
  {
    momentum += particles.mass[p] * particles.velocity[p].dot(flight_axis);
    mass += particles.mass[p];
  }
  double sums[2] = {momentum, mass};
  ranks.sum(sums, 2);
  const double speed = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
  if (!(speed > 0.0))
    return end; // stopped or going back: nothing to extrapolate
  return std::min(end, current_time + std::max(0.0, exit_plane - tail) / speed);
}

std::vector<char> Solver::bodies_with_plastic_history() const
{
  std::vector<char> flags;
  for (const materials::Material* material : materials_of_body)
    flags.push_back(material->has_plastic_history());
  return flags;
}

double* Solver::volumetric_rate_or_null()
{
  if (!stress_settings.uses_viscosity())
    return nullptr;
  volumetric_rate.resize(particles.size(), 0.0);
  return volumetric_rate.data();
}

void Solver::sort_points()
{
  // A counting sort by cell within each body: stable, linear in points plus cells, with
  // 32-bit keys and order (8 bytes of scratch per point; a rank holds fewer than 2^32 points
  // and the padded grid fewer than 2^32 cells, which the grid's limit of 2^31 nodes ensures).
  const auto& n = grid.cells();
  const std::int64_t extent[3] = {n[0] + 5, n[1] + 5, n[2] + 5};
  const std::size_t n_keys = static_cast<std::size_t>(extent[0] * extent[1] * extent[2]);
  const long n_points = static_cast<long>(particles.size());
  std::vector<std::uint32_t> cell_key(particles.size());
#pragma omp parallel for schedule(static)
  for (long p = 0; p < n_points; ++p)
  {
    const Vector3 s = grid.to_cell_units(particles.position[p]);
    std::int64_t ijk[3];
    for (int d = 0; d < 3; ++d) // clamped: a point far outside only lands in an edge cell
      ijk[d] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(s[d])) + 2, 0,
                                        extent[d] - 1);
    cell_key[p] = static_cast<std::uint32_t>(ijk[0] + extent[0] * (ijk[1] + extent[1] * ijk[2]));
  }
  std::vector<std::uint32_t> order(particles.size());
  std::vector<std::uint32_t> first_of_key(n_keys + 1);
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
  {
    const std::size_t begin = particles.begin_of(b), end = particles.end_of(b);
    std::fill(first_of_key.begin(), first_of_key.end(), 0u);
    for (std::size_t p = begin; p < end; ++p)
      ++first_of_key[cell_key[p] + 1];
    std::partial_sum(first_of_key.begin(), first_of_key.end(), first_of_key.begin());
    for (std::size_t p = begin; p < end; ++p)
      order[begin + first_of_key[cell_key[p]]++] = static_cast<std::uint32_t>(p);
  }
  particles.permute(order);
}

void Solver::remove_points_outside_grid()
{
  const Vector3 lower = grid.origin().array() - grid.cell_size();
  const Vector3 upper = grid.upper_corner().array() + 0.999 * grid.cell_size();
  // NaN is a blow-up, not an outflow: check_state reports it.
  auto leaves = [&](const Vector3& x) {
    return x.allFinite() &&
           !((x.array() >= lower.array()).all() && (x.array() <= upper.array()).all());
  };
  const long n = static_cast<long>(particles.size());
  long n_leaving = 0;
#pragma omp parallel for schedule(static) reduction(+ : n_leaving)
  for (long p = 0; p < n; ++p)
    n_leaving += leaves(particles.position[p]);
  // This step's outflow: count, energy, momentum, then each body's mass; summed over the ranks.
  std::vector<double> outflow(5 + particles.n_bodies(), 0.0);
  outflow[0] = static_cast<double>(n_leaving);
  if (n_leaving > 0)
  {
    std::vector<char> keep(particles.size(), 1);
    for (long p = 0; p < n; ++p)
    {
      if (!leaves(particles.position[p]))
        continue;
      keep[p] = 0;
      const std::size_t b = particles.body_of(p);
      departed.push_back({particles.reference_position[p].cast<double>(),
                          particles.reference_volume[p], particles.failure[p],
                          static_cast<std::uint32_t>(b)});
      const double m = particles.mass[p];
      outflow[5 + b] += m;
      outflow[1] += 0.5 * m * particles.velocity[p].squaredNorm() +
                    particles.reference_volume[p] *
                      (particles.energy_density[p] + particles.dissipated_density[p]);
      for (int d = 0; d < 3; ++d)
        outflow[2 + d] += m * particles.velocity[p][d];
    }
    particles.keep_only(keep);
  }
  ranks.sum(outflow.data(), static_cast<int>(outflow.size()));
  // A body's mass is that of its points on the grid: a rigid body half out of it answers the
  // contact force with what is left, as the momentum its departed points took is frozen.
  for (std::size_t b = 0; b < body_mass.size(); ++b)
    body_mass[b] = std::max(0.0, body_mass[b] - outflow[5 + b]);
  n_removed += static_cast<std::size_t>(outflow[0]);
  outflow_energy += outflow[1];
  const Vector3 momentum_out(outflow[2], outflow[3], outflow[4]);
  outflow_momentum += parameters.axisymmetric ? revolved(momentum_out) : momentum_out;
}

} // namespace vulnus::mpm
