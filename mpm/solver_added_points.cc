// Material added to a body during a run (the adaptive zone turns far-field cells into points):
// fresh ids, stresses from the body's law, and the points' way to the ranks that hold them.
#include "mpm/solver.h"

#include <cmath>
#include <vector>

namespace vulnus::mpm
{
void Solver::assign_fresh_ids(Particles& added)
{
  // Ids continue after the largest in use, rank by rank.
  double largest = -1.0;
  for (const std::uint32_t id : particles.id)
    largest = std::max(largest, static_cast<double>(id));
  largest = ranks.max(largest);
  std::vector<std::uint64_t> counts(static_cast<std::size_t>(ranks.size()), 0);
  counts[static_cast<std::size_t>(ranks.rank())] = added.size();
  ranks.sum(counts.data(), static_cast<int>(counts.size()));
  std::uint64_t next = static_cast<std::uint64_t>(largest + 1.0);
  for (int r = 0; r < ranks.rank(); ++r)
    next += counts[static_cast<std::size_t>(r)];
  for (std::uint32_t& id : added.id)
    id = static_cast<std::uint32_t>(next++);
}

double Solver::add_points(const std::size_t b, Particles added)
{
  assign_fresh_ids(added);
  const materials::Material& law = *materials_of_body[b];
  double energy = 0.0, mass = 0.0;
  Vector3 momentum = Vector3::Zero();
  for (std::size_t p = 0; p < added.size(); ++p)
  {
    materials::PointState state;
    state.failure = added.failure[p];
    if (const materials::PlasticHistory* history = added.plastic_of(p))
      state.plastic = *history;
    materials::PointResponse response;
    // On a copy: the history stays as handed over; the next step updates it from there.
    law.update(added.deformation_gradient[p],
               added.fiber_direction[p].cast<double>().normalized(), state, response);
    added.stress[p] = symmetric_part(response.cauchy_stress);
    added.energy_density[p] = response.energy_density;
    added.dissipated_density[p] = 0.0;
    const double density = added.mass[p] / (added.reference_volume[p] *
                                            added.deformation_gradient[p].determinant());
    added.wave_speed[p] = response.p_wave_modulus > 0.0
                            ? std::sqrt(response.p_wave_modulus / density)
                            : 0.0;
    energy += 0.5 * added.mass[p] * added.velocity[p].squaredNorm() +
              response.energy_density * added.reference_volume[p];
    mass += added.mass[p];
    momentum += added.mass[p] * added.velocity[p];
  }
  particles.insert_into_body(b, added);
  double sums[5] = {energy, mass, momentum[0], momentum[1], momentum[2]};
  ranks.sum(sums, 5);
  body_mass[b] += sums[1];
  accumulated_added_momentum += Vector3(sums[2], sums[3], sums[4]);
  migrate_points(true);
  sort_points();
  return sums[0];
}
} // namespace vulnus::mpm
