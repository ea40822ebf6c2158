// What a run that goes on past the projectile's exit needs to report: the projectile's state
// when it left the target, how deep it went (and whether it stopped), and the impulse the
// domain faces' supports gave the target.
#include "mpm/solver.h"

#include <algorithm>
#include <limits>

namespace vulnus::mpm
{
bool Solver::projectile_near_target() const
{
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vector3 low(inf, inf, inf), high(-inf, -inf, -inf);
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
    if (static_cast<int>(b) != projectile_body)
      for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
        if (particles.failure[p] != materials::total_failure)
        {
          low = low.cwiseMin(particles.position[p]);
          high = high.cwiseMax(particles.position[p]);
        }
  double box[6] = {-low[0], -low[1], -low[2], high[0], high[1], high[2]};
  ranks.max(box, 6);
  const double reach = parameters.cell_size;
  low = Vector3(-box[0], -box[1], -box[2]).array() - reach;
  high = Vector3(box[3], box[4], box[5]).array() + reach;
  double near = 0.0;
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
    if ((particles.position[p].array() >= low.array()).all() &&
        (particles.position[p].array() <= high.array()).all())
    {
      near = 1.0;
      break;
    }
  return ranks.max(near) > 0.0;
}

void Solver::record_projectile_exit()
{
  if (exit_record.recorded || projectile_body < 0 || particles.n_bodies() < 2)
    return;
  const bool past_exit_plane = projectile_tail() > exit_plane;
  if (!past_exit_plane)
  {
    const bool near = projectile_near_target();
    if (near || !projectile_reached_target)
    {
      projectile_reached_target = projectile_reached_target || near;
      return;
    }
  }
  double sums[8] = {0, 0, 0, 0, 0, 0, 0, 0}; // mass, momentum, kinetic energy, first moment
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
  {
    const double m = particles.mass[p];
    sums[0] += m;
    for (int d = 0; d < 3; ++d)
    {
      sums[1 + d] += m * particles.velocity[p][d];
      sums[5 + d] += m * particles.position[p][d];
    }
    sums[4] += 0.5 * m * particles.velocity[p].squaredNorm();
  }
  ranks.sum(sums, 8);
  exit_record.recorded = true;
  exit_record.past_exit_plane = past_exit_plane;
  exit_record.time = current_time;
  if (sums[0] > 0.0)
  {
    exit_record.velocity = Vector3(sums[1], sums[2], sums[3]) / sums[0];
    exit_record.position = Vector3(sums[5], sums[6], sums[7]) / sums[0];
  }
  exit_record.kinetic_energy = sums[4];
}

void Solver::record_penetration()
{
  if (projectile_body < 0 || particles.n_bodies() < 2)
    return;
  double nose = -std::numeric_limits<double>::max();
  double sums[2] = {0.0, 0.0}; // momentum along the flight, mass
  for (std::size_t p = particles.begin_of(projectile_body); p < particles.end_of(projectile_body); ++p)
  {
    nose = std::max(nose, particles.position[p].dot(flight_axis));
    sums[0] += particles.mass[p] * particles.velocity[p].dot(flight_axis);
    sums[1] += particles.mass[p];
  }
  nose = ranks.max(nose);
  ranks.sum(sums, 2);
  if (!(sums[1] > 0.0))
    return;
  penetration_record.record(current_time, nose + nose_offset - entrance_plane, sums[0] / sums[1],
                            parameters.projectile_stop_speed);
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
