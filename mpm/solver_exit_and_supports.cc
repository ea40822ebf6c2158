// What a run that goes on past the projectile's exit needs to report: the projectile's state
// when it left the target, and the impulse the domain faces' supports gave the target.
#include "mpm/solver.h"

namespace vulnus::mpm
{
void Solver::record_projectile_exit()
{
  if (exit_record.recorded || projectile_body < 0 || particles.n_bodies() < 2)
    return;
  if (!(projectile_tail() > exit_plane))
    return;
  double sums[5] = {0, 0, 0, 0, 0}; // mass, momentum, kinetic energy
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
  {
    const double m = particles.mass[p];
    sums[0] += m;
    for (int d = 0; d < 3; ++d)
      sums[1 + d] += m * particles.velocity[p][d];
    sums[4] += 0.5 * m * particles.velocity[p].squaredNorm();
  }
  ranks.sum(sums, 5);
  exit_record.recorded = true;
  exit_record.time = current_time;
  if (sums[0] > 0.0)
    exit_record.velocity = Vector3(sums[1], sums[2], sums[3]) / sums[0];
  exit_record.kinetic_energy = sums[4];
}

std::array<Vector3, 6> Solver::support_impulses() const
{
  double packed[18];
  for (int f = 0; f < 6; ++f)
    for (int d = 0; d < 3; ++d)
      packed[3 * f + d] = support_impulse_here[f][d];
  ranks.sum(packed, 18);
  std::array<Vector3, 6> total;
  for (int f = 0; f < 6; ++f)
    total[f] = Vector3(packed[3 * f], packed[3 * f + 1], packed[3 * f + 2]);
  return total;
}
} // namespace vulnus::mpm
