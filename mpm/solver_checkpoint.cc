// Binary checkpoint of the MPM solver state: a tagged header, the scene's body layout (to
// refuse a checkpoint of another scene), every point array and the accumulated scalars.
#include "mpm/solver.h"

#include "mpm/binary_io.h"

#include <algorithm>
#include <istream>
#include <ostream>

namespace vulnus::mpm
{
namespace
{
using namespace binary;

constexpr char magic[8] = {'V', 'U', 'L', 'N', 'U', 'S', 'D', '2'};
} // namespace

void Solver::save(std::ostream& out) const
{
  out.write(magic, sizeof(magic));
  put(out, static_cast<std::uint64_t>(parameters.bodies.size()));
  put_vector(out, particles.body_begin);
  particles.for_each_array([&out](const auto& values) { put_vector(out, values); });
  put_vector(out, particles.plastic_pool);
  put_vector(out, grid_settings.rigid_velocity);
  put_vector(out, peak_yield_ratio);
  put_vector(out, peak_point_speed);
  put_vector(out, body_mass); // of the points still on the grid
  // What the history reports of the last step: a run restored at its final step writes it.
  put_vector(out, grid_result.contact_force);
  put(out, static_cast<std::uint64_t>(grid_result.n_contact_nodes));
  put(out, static_cast<std::uint64_t>(n_active_last_step));
  put(out, current_time);
  put(out, time_step);
  put(out, static_cast<std::uint64_t>(n_steps));
  put(out, accumulated_contact_dissipation);
  put(out, accumulated_support_dissipation);
  put(out, energy_at_start);
  put(out, momentum_at_start);
  put(out, accumulated_external_impulse);
  put(out, accumulated_prescribed_work);
  put(out, accumulated_added_momentum);
  put(out, static_cast<std::uint64_t>(n_removed));
  put(out, static_cast<std::uint64_t>(n_split));
  put(out, outflow_energy);
  put(out, outflow_momentum);
  std::vector<double> departed_packed; // x, y, z, volume, failure, body
  for (const DepartedPoint& d : departed)
    departed_packed.insert(departed_packed.end(),
                           {d.reference_position[0], d.reference_position[1], d.reference_position[2],
                            d.reference_volume, double(d.failure), double(d.body)});
  put_vector(out, departed_packed);
  put(out, static_cast<std::uint64_t>(exit_record.recorded));
  put(out, exit_record.time);
  put(out, exit_record.velocity);
  put(out, exit_record.kinetic_energy);
  put(out, exit_record.position);
  put(out, static_cast<std::uint64_t>(exit_record.past_exit_plane));
  put(out, static_cast<std::uint64_t>(projectile_reached_target));
  put_vector(out, penetration_record.packed());
  put_vector(out, rigid_hold.packed());
  put_text(out, rigid_hold.record().reason);
  put_vector(out, rotation_estimate.packed());
  for (const Vector3& impulse : support_impulse_here)
    put(out, impulse);
  put(out, static_cast<std::uint64_t>(ranks.size()));
  put(out, static_cast<std::int32_t>(partition.axis()));
  put_vector(out, partition.first_layers());
  out.write(magic, sizeof(magic)); // trailer: a complete checkpoint ends with the tag
  if (!out)
    throw std::runtime_error("checkpoint could not be written");
}

void Solver::restore(std::istream& in)
{
  expect_tag(in, magic, "not a vulnus MPM checkpoint (bad header)");
  std::uint64_t n_bodies = 0;
  get(in, n_bodies);
  if (n_bodies != parameters.bodies.size())
    throw std::runtime_error("checkpoint has " + std::to_string(n_bodies) + " bodies, the deck " +
                             std::to_string(parameters.bodies.size()) + ": it belongs to another scene");
  Particles loaded;
  get_vector(in, loaded.body_begin);
  loaded.for_each_array([&in](auto& values) { get_vector(in, values); });
  get_vector(in, loaded.plastic_pool);
  std::vector<Vector3> rigid_velocity;
  std::vector<double> peak;
  get_vector(in, rigid_velocity);
  get_vector(in, peak);
  std::vector<double> peak_speed;
  get_vector(in, peak_speed);
  std::vector<double> mass_on_grid;
  get_vector(in, mass_on_grid);
  std::vector<Vector3> contact_force;
  std::uint64_t contact_nodes = 0, active = 0;
  get_vector(in, contact_force);
  get(in, contact_nodes);
  get(in, active);
  double time = 0, step = 0, contact = 0, supports = 0, energy = 0, outflow = 0;
  std::uint64_t steps = 0, removed = 0, split = 0;
  Vector3 outflow_p;
  get(in, time);
  get(in, step);
  get(in, steps);
  get(in, contact);
  get(in, supports);
  get(in, energy);
  Vector3 momentum_start, external, added;
  get(in, momentum_start);
  get(in, external);
  double prescribed_work = 0.0;
  get(in, prescribed_work);
  get(in, added);
  get(in, removed);
  get(in, split);
  get(in, outflow);
  get(in, outflow_p);
  std::vector<double> departed_packed;
  get_vector(in, departed_packed);
  std::uint64_t exit_recorded = 0;
  ProjectileExit exit_loaded;
  get(in, exit_recorded);
  get(in, exit_loaded.time);
  get(in, exit_loaded.velocity);
  get(in, exit_loaded.kinetic_energy);
  get(in, exit_loaded.position);
  std::uint64_t past_exit_plane = 0, reached_target = 0;
  get(in, past_exit_plane);
  get(in, reached_target);
  std::vector<double> penetration_packed;
  get_vector(in, penetration_packed);
  std::vector<double> hold_packed;
  std::string hold_reason;
  get_vector(in, hold_packed);
  get_text(in, hold_reason);
  std::vector<double> rotation_packed;
  get_vector(in, rotation_packed);
  exit_loaded.recorded = exit_recorded != 0;
  exit_loaded.past_exit_plane = past_exit_plane != 0;
  std::array<Vector3, 6> supports_loaded;
  for (Vector3& impulse : supports_loaded)
    get(in, impulse);
  std::uint64_t n_ranks = 0;
  std::int32_t slab_axis = 0;
  std::vector<int> first_layers;
  get(in, n_ranks);
  get(in, slab_axis);
  get_vector(in, first_layers);
  expect_tag(in, magic, "checkpoint is incomplete (no trailer)");
  const std::size_t n = loaded.position.size();
  bool sizes_agree = departed_packed.size() % 6 == 0 &&
                     loaded.body_begin.size() == n_bodies + 1 && loaded.body_begin.back() == n &&
                     loaded.body_begin.front() == 0 &&
                     std::is_sorted(loaded.body_begin.begin(), loaded.body_begin.end()) &&
                     rigid_velocity.size() == n_bodies && peak.size() == n_bodies &&
                     peak_speed.size() == n_bodies && mass_on_grid.size() == n_bodies;
  loaded.for_each_array([&](const auto& values) { sizes_agree = sizes_agree && values.size() == n; });
  if (!sizes_agree)
    throw std::runtime_error("checkpoint is inconsistent (array sizes differ)");
  const std::vector<char> plastic_bodies = bodies_with_plastic_history();
  if (const long b = loaded.body_with_invalid_plastic_slots(&plastic_bodies); b >= 0)
    throw std::runtime_error("checkpoint is inconsistent (plastic histories of body " +
                             parameters.bodies[b].name + ")");

  if (n_ranks != static_cast<std::uint64_t>(ranks.size()))
    throw std::runtime_error("checkpoint was written by " + std::to_string(n_ranks) +
                             " MPI rank(s); restart it on the same number (this run has " +
                             std::to_string(ranks.size()) + ")");
  SlabPartition slabs;
  try
  {
    slabs = SlabPartition::from_layers(slab_axis, first_layers);
  }
  catch (const std::invalid_argument&)
  {
    throw std::runtime_error("checkpoint is inconsistent (slab cuts)");
  }
  partition = slabs;
  particles = std::move(loaded);
  grid_settings.rigid_velocity = rigid_velocity;
  kinematics.rigid_velocity = rigid_velocity;
  peak_yield_ratio = peak;
  peak_point_speed = peak_speed;
  grid_result.contact_force = contact_force;
  grid_result.n_contact_nodes = contact_nodes;
  n_active_last_step = active;
  current_time = time;
  time_step = step;
  n_steps = steps;
  accumulated_contact_dissipation = contact;
  accumulated_support_dissipation = supports;
  energy_at_start = energy;
  momentum_at_start = momentum_start;
  accumulated_external_impulse = external;
  accumulated_prescribed_work = prescribed_work;
  accumulated_added_momentum = added;
  n_removed = removed;
  n_split = split;
  body_mass = mass_on_grid;
  outflow_energy = outflow;
  outflow_momentum = outflow_p;
  departed.clear();
  for (std::size_t k = 0; k + 5 < departed_packed.size(); k += 6)
    departed.push_back({Vector3(departed_packed[k], departed_packed[k + 1], departed_packed[k + 2]),
                        departed_packed[k + 3], static_cast<std::uint8_t>(departed_packed[k + 4]),
                        static_cast<std::uint32_t>(departed_packed[k + 5])});
  exit_record = exit_loaded;
  penetration_record.unpack(penetration_packed);
  const bool held_before = rigid_hold.record().held;
  rigid_hold.unpack(hold_packed, hold_reason);
  if (held_before != rigid_hold.record().held)
  {
    if (!held_before)
      throw std::runtime_error("checkpoint holds the projectile rigid while this deck does not "
                               "(Time/Rigid projectile while elastic): restart with the deck "
                               "that wrote it");
    make_projectile_deformable();
  }
  rotation_estimate.unpack(rotation_packed);
  projectile_reached_target = reached_target != 0;
  support_impulse_here = supports_loaded;
}
} // namespace vulnus::mpm
