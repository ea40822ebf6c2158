// Reductions over the points for the time history.
#include "mpm/diagnostics.h"

#include <algorithm>
#include <limits>

namespace vulnus::mpm
{
SceneDiagnostics compute_diagnostics(const Particles& particles, const Vector3& direction,
                                     const Vector3& gravity)
{
  SceneDiagnostics d;
  const std::size_t n_bodies = particles.n_bodies();
  d.bodies.resize(n_bodies);
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    const long begin = particles.begin_of(b), end = particles.end_of(b);
    double mass = 0, kinetic = 0, strain = 0, dissipated = 0;
    double cx = 0, cy = 0, cz = 0, px = 0, py = 0, pz = 0;
    double lo = std::numeric_limits<double>::max(), hi = -std::numeric_limits<double>::max();
    std::size_t c0 = 0, c1 = 0, c2 = 0, c3 = 0;
#pragma omp parallel for schedule(static) reduction(+ : mass, kinetic, strain, dissipated, cx, cy, cz, px, py, pz, c0, c1, c2, c3) reduction(min : lo) reduction(max : hi)
    for (long p = begin; p < end; ++p)
    {
      const double m = particles.mass[p];
      const Vector3& x = particles.position[p];
      const Vector3& v = particles.velocity[p];
      mass += m;
      kinetic += 0.5 * m * v.squaredNorm();
      strain += particles.reference_volume[p] * particles.energy_density[p];
      dissipated += particles.reference_volume[p] * particles.dissipated_density[p];
      cx += m * x[0];
      cy += m * x[1];
      cz += m * x[2];
      px += m * v[0];
      py += m * v[1];
      pz += m * v[2];
      const double along = x.dot(direction);
      lo = std::min(lo, along);
      hi = std::max(hi, along);
      switch (particles.failure[p])
      {
        case 0: ++c0; break;
        case 1: ++c1; break;
        case 2: ++c2; break;
        default: ++c3; break;
      }
    }
    BodySummary& s = d.bodies[b];
    s.mass = mass;
    s.centroid = mass > 0 ? Vector3(Vector3(cx, cy, cz) / mass) : Vector3(Vector3::Zero());
    s.velocity = mass > 0 ? Vector3(Vector3(px, py, pz) / mass) : Vector3(Vector3::Zero());
    s.kinetic_energy = kinetic;
    s.strain_energy = strain;
    s.dissipated_energy = dissipated;
    s.min_along = lo;
    s.max_along = hi;
    d.kinetic_energy += kinetic;
    d.strain_energy += strain;
    d.dissipated_energy += dissipated;
    d.momentum += Vector3(px, py, pz);
    d.potential_energy -= gravity.dot(Vector3(cx, cy, cz));
    d.failure_counts[0] += c0;
    d.failure_counts[1] += c1;
    d.failure_counts[2] += c2;
    d.failure_counts[3] += c3;
  }
  return d;
}
} // namespace vulnus::mpm
