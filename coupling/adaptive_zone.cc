// The adaptive MPM zone (docs/adaptive_zone.md): far-field cells whose material nears failure
// become material points. The zone stays a box on grid nodes and grows to hold them; the far
// field's mesh has the grid's cells wherever the zone may grow, so the grown far field is the
// same mesh with the converted cells switched off, its state left where it is. Mass and momentum pass to the points exactly (the lattice integrates the
// trilinear fields exactly); the kinetic energy drops by the lumped-minus-consistent
// difference of the converted cells, which each conversion records.
#include "coupling/hybrid_solver.h"

#include "materials/fiber_field.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

namespace vulnus::coupling
{
namespace
{
double energy_of_both(const mpm::SceneDiagnostics& m, const fem::FeDiagnostics& f)
{
  return m.kinetic_energy + m.strain_energy + f.kinetic_energy + f.strain_energy;
}
} // namespace

HybridSolver::ZoneNeed HybridSolver::zone_needed()
{
  const auto start = std::chrono::steady_clock::now();
  std::array<double, 3> lo = split.hybrid.zone_min, hi = split.hybrid.zone_max;
  const double h = split.mpm.cell_size;
  const double origin[3] = {split.mpm.domain_min[0], split.mpm.domain_min[1],
                            split.mpm.domain_min[2]};
  const double reach = (split.hybrid.adaptive.margin_cells + 0.5) * h;
  const AdaptiveZoneParameters& rules = split.hybrid.adaptive;
  std::uint64_t beyond = 0;
  std::vector<std::pair<dealii::Point<3>, ZoneCause>> places;
  for (const dealii::Point<3>& c : fe_solver->cells_nearing_failure(rules.threshold))
    places.emplace_back(c, ZoneCause::failure);
  if (rules.interface_motion == InterfaceMotion::total)
  {
    // Interface nodes that moved too far from their grid nodes, from every rank.
    std::vector<double> moved;
    for (const fem::NodeRecord& node : fe_solver->interface_nodes())
      if (fe_solver->displacement(node).norm() > rules.interface_displacement * h)
        moved.insert(moved.end(), {node.position[0], node.position[1], node.position[2]});
    for (const std::vector<double>& theirs : dealii::Utilities::MPI::all_gather(comm, moved))
      for (std::size_t i = 0; i + 2 < theirs.size(); i += 3)
        places.emplace_back(dealii::Point<3>(theirs[i], theirs[i + 1], theirs[i + 2]),
                            ZoneCause::interface_motion);
  }
  fem::CellMotionLimits limits;
  limits.non_affine =
    rules.interface_motion == InterfaceMotion::non_affine ? rules.interface_displacement : 0.0;
  limits.deviatoric_stretch = rules.distortion;
  limits.jacobian_ratio = rules.jacobian_ratio;
  if (limits.non_affine > 0.0 || limits.deviatoric_stretch > 0.0 || limits.jacobian_ratio > 0.0)
    for (const fem::FlaggedCell& cell : fe_solver->cells_moving_unlike_elements(limits))
      places.emplace_back(cell.centre, cell.cause == fem::CellMotionCause::distortion
                                         ? ZoneCause::distortion
                                         : ZoneCause::interface_motion);
  ZoneFlags flagged{};
  for (const auto& [c, cause] : places)
  {
    bool inside_limit = true;
    for (int d = 0; d < 3; ++d)
      inside_limit = inside_limit && c[d] >= split.limit_min[d] - 1e-9 * h &&
                     c[d] <= split.limit_max[d] + 1e-9 * h;
    if (!inside_limit)
    {
      ++beyond;
      continue;
    }
    ++flagged[static_cast<int>(cause)];
    bool cut_by_limit = false;
    for (int d = 0; d < 3; ++d)
    {
      const double below = origin[d] + h * std::floor((c[d] - reach - origin[d]) / h + 1e-9);
      const double above = origin[d] + h * std::ceil((c[d] + reach - origin[d]) / h - 1e-9);
      // The limit cuts what the place needs, unless it is the body's own face.
      cut_by_limit = cut_by_limit ||
                     (below < split.limit_min[d] - 1e-9 * h &&
                      split.limit_min[d] > split.fe.slab_min[d] + 1e-9 * h) ||
                     (above > split.limit_max[d] + 1e-9 * h &&
                      split.limit_max[d] < split.fe.slab_max[d] - 1e-9 * h);
      lo[d] = std::min(lo[d], std::max(below, split.limit_min[d]));
      hi[d] = std::max(hi[d], std::min(above, split.limit_max[d]));
    }
    beyond += cut_by_limit;
  }
  // The limit and the grid-node bounds are computed differently and may differ in the last
  // bit: a bound that did not move by a cell's 1e-9 is the zone's own, so that a zone at its
  // limit is not rebuilt for nothing.
  for (int d = 0; d < 3; ++d)
  {
    if (std::abs(lo[d] - split.hybrid.zone_min[d]) < 1e-9 * h)
      lo[d] = split.hybrid.zone_min[d];
    if (std::abs(hi[d] - split.hybrid.zone_max[d]) < 1e-9 * h)
      hi[d] = split.hybrid.zone_max[d];
  }
  n_cells_beyond_limit = std::max(n_cells_beyond_limit, beyond);
  check_seconds +=
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {lo, hi, flagged};
}

void HybridSolver::grow_zone(const std::array<double, 3>& new_min,
                             const std::array<double, 3>& new_max, const ZoneFlags& flagged)
{
  const double h = split.mpm.cell_size;
  for (int d = 0; d < 3; ++d)
    if (new_min[d] > split.hybrid.zone_min[d] + 1e-9 * h ||
        new_max[d] < split.hybrid.zone_max[d] - 1e-9 * h ||
        new_min[d] < split.limit_min[d] - 1e-9 * h || new_max[d] > split.limit_max[d] + 1e-9 * h)
      throw std::logic_error("adaptive zone: the new zone must hold the old one within the limit");

  const auto start = std::chrono::steady_clock::now();
  ZoneConversion record;
  record.time = mpm_solver->time();
  record.mpm_step = mpm_solver->step_count();
  record.zone_min = new_min;
  record.zone_max = new_max;
  record.energy_before = energy_of_both(mpm_solver->diagnostics(), fe_solver->diagnostics());
  record.momentum_before = total_momentum();
  record.flagged = flagged;
  const unsigned long long cells_before = fe_solver->n_active_cells();

  // The converted cells' material as points of the split body (each rank its own cells).
  const std::size_t body = split.coupled_body;
  const mpm::BodyParameters& slab = split.mpm.bodies[body];
  const bool plastic = mpm_solver->body_material(body).has_plastic_history();
  const bool fibers = mpm_solver->body_material(body).uses_fibers();
  mpm::Particles added;
  added.start_body();
  double volume = 0.0;
  for (const fem::ConvertedPoint& p :
       fe_solver->material_points_inside(new_min, new_max, slab.particles_per_cell))
  {
    const mpm::Vector3 X(p.reference_position[0], p.reference_position[1], p.reference_position[2]);
    const mpm::Vector3 u(p.displacement[0], p.displacement[1], p.displacement[2]);
    const mpm::Vector3 v(p.velocity[0], p.velocity[1], p.velocity[2]);
    const mpm::Vector3 fiber =
      fibers ? materials::fiber_direction(slab.fibers, X) : mpm::Vector3::UnitX();
    added.append(X + u, v, p.mass, p.reference_volume, fiber, plastic);
    const std::size_t i = added.size() - 1;
    added.reference_position[i] = X.cast<float>();
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        added.deformation_gradient[i](a, b) = p.deformation_gradient[a][b];
    added.domain[i] = (added.deformation_gradient[i] * added.domain[i].cast<double>()).cast<float>();
    added.failure[i] = p.state.failure;
    if (materials::PlasticHistory* history = added.plastic_of(i))
      *history = p.state.plastic;
    volume += p.reference_volume;
  }
  added.finish_body();
  const std::uint64_t n_added = added.size();

  // The far field without them (its mesh keeps the start zone's hole: a restart builds that
  // and converts the same cells).
  split.hybrid.zone_min = new_min;
  split.hybrid.zone_max = new_max;
  for (int d = 0; d < 3; ++d)
  {
    split.mpm.bodies[body].box_min[d] = new_min[d];
    split.mpm.bodies[body].box_max[d] = new_max[d];
  }
  fe_solver->convert_cells_inside(new_min, new_max);

  // The impulse still in transit, by grid key: it stays on nodes that remain on the
  // interface; a node that is now inside the zone hands it to the nearest interface node.
  std::map<std::int64_t, mpm::Vector3> pending;
  for (std::size_t k = 0; k < keys.size(); ++k)
    pending[keys[k]] = created[k] - correction[k];
  match_interface_nodes(comm);
  for (std::vector<mpm::Vector3>* v : {&velocity_start, &velocity_end, &created, &correction})
    v->assign(keys.size(), mpm::Vector3::Zero());
  // Balanced windows: the interface changed, so does the far field's effective mass.
  balance_matrix.resize(0, 0);
  const mpm::Grid& grid = mpm_solver->background_grid();
  for (const auto& [key, impulse] : pending)
  {
    if (keys.empty())
    {
      impulse_left_by_retirement -= impulse; // impulse_in_transit counts created with a minus
      continue;
    }
    const auto at = std::lower_bound(keys.begin(), keys.end(), key);
    std::size_t k = static_cast<std::size_t>(at - keys.begin());
    if (at == keys.end() || *at != key)
    {
      const mpm::Vector3 x = grid.node_position(key);
      double nearest = std::numeric_limits<double>::max();
      for (std::size_t j = 0; j < keys.size(); ++j)
        if (const double r = (grid.node_position(keys[j]) - x).squaredNorm(); r < nearest)
        {
          nearest = r;
          k = j;
        }
    }
    created[k] += impulse;
  }

  const double added_energy = mpm_solver->add_points(body, std::move(added));
  (void)added_energy;
  if (follows_interface())
    place_interface();
  else
    mpm_solver->share_nodes({body, keys, this});

  std::uint64_t counts[1] = {n_added};
  mpm_solver->rank_group().sum(counts, 1);
  double sums[1] = {volume};
  mpm_solver->rank_group().sum(sums, 1);
  record.cells = cells_before - fe_solver->n_active_cells();
  record.points = counts[0];
  record.volume = sums[0];
  record.mass = sums[0] * split.fe.density;
  record.energy_after = energy_of_both(mpm_solver->diagnostics(), fe_solver->diagnostics());
  record.momentum_after = total_momentum();
  record.seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  zone_conversions.push_back(record);
  retire_far_field_if_empty();
}

void HybridSolver::retire_far_field_if_empty()
{
  if (retired || fe_solver->n_active_cells() > 0)
    return;
  retired = true;
  window_open = false;
  mpm_solver->share_nodes({split.coupled_body, {}, nullptr});
}

void HybridSolver::retire_far_field_without_stiffness()
{
  // A far field of debris only (every live cell failed, no wave speed) cannot choose a step
  // nor carry a load: its material goes to the zone, which may then hold the whole body.
  if (std::isfinite(fe_solver->shortest_wave_transit()))
    return;
  const double h = split.mpm.cell_size;
  for (int d = 0; d < 3; ++d)
    if (split.limit_min[d] > split.fe.slab_min[d] + 1e-9 * h ||
        split.limit_max[d] < split.fe.slab_max[d] - 1e-9 * h)
      throw std::runtime_error(
        "adaptive zone: every far-field cell left has failed (no stiffness, no stable step) "
        "at t = " + std::to_string(mpm_solver->time()) +
        " s, but the zone may not grow past its reach to take them in; raise Hybrid/Adaptive "
        "zone reach to the slab's faces (so the run can continue as pure MPM), or run the "
        "scene as pure MPM");
  grow_zone(split.limit_min, split.limit_max);
}
} // namespace vulnus::coupling
