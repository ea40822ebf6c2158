// Material updates of the points, per body and per block, with threads over blocks.
#include "mpm/stress_update.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vulnus::mpm
{
namespace
{
constexpr long block_size = 512;

/// Updates points [begin, end) of one body; returns the viscous dissipation (J).
double update_range(const StressUpdateSettings& s, const materials::Material& material,
                    const double density, const double* volumetric_rate,
                    Particles& particles, const long begin, const long end,
                    std::vector<materials::PointResponse>& responses, double& max_ratio)
{
  double viscous = 0.0;
  materials::PointBlock block;
  block.n_points = static_cast<std::size_t>(end - begin);
  block.deformation_gradients = &particles.deformation_gradient[begin];
  block.fiber_directions = material.uses_fibers() ? &particles.fiber_direction[begin] : nullptr;
  block.failure = &particles.failure[begin];
  if (material.has_plastic_history())
  {
    block.plastic = particles.plastic_pool.data();
    block.plastic_slots = &particles.plastic_slot[begin];
  }
  block.responses = responses.data();
  block.time_step = s.time_step;
  material.update_block(block);
  for (long p = begin; p < end; ++p)
  {
    const materials::PointResponse& r = responses[p - begin];
    const double J = particles.deformation_gradient[p].determinant();
    const double current_density = density / J;
    double wave_speed = std::sqrt(r.p_wave_modulus / current_density);
    Tensor2 sigma = r.cauchy_stress;
    double dissipated = r.dissipated_density;
    const double rate = volumetric_rate ? volumetric_rate[p] : 0.0;
    // The viscosity acts in compression only, so a graded grid's cell is looked up only then.
    const bool compressing = rate < 0.0 && s.viscosity.active();
    const double length = !compressing ? 0.0
                          : s.graded_grid ? s.graded_grid->widest_cell_side(particles.position[p])
                                          : s.cell_size;
    if (const double q = compressing ? s.viscosity.pressure(current_density, wave_speed, length, rate)
                                     : 0.0;
        q > 0.0)
    {
      sigma.diagonal().array() -= q;
      const double viscous_density = q * -rate * J * s.time_step;
      dissipated += viscous_density;
      viscous += viscous_density * particles.reference_volume[p];
      wave_speed += std::sqrt(q / current_density);
    }
    particles.stress[p] = symmetric_part(sigma);
    particles.energy_density[p] = r.energy_density;
    particles.dissipated_density[p] += dissipated;
    particles.wave_speed[p] = wave_speed;
    max_ratio = std::max(max_ratio, r.von_mises_over_yield);
  }
  return viscous;
}
} // namespace

void update_stresses(const StressUpdateSettings& s, const double* volumetric_rate,
                     Particles& particles, StressUpdateResult& result)
{
  const std::size_t n_bodies = particles.n_bodies();
  result.max_von_mises_over_yield.assign(n_bodies, 0.0);
  result.viscous_dissipation = 0.0;
  result.failed_point = -1;
  result.failure_message.clear();
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    const materials::Material& material = *s.body_material[b];
    if (material.is_rigid() || (!s.body_advanced_elsewhere.empty() && s.body_advanced_elsewhere[b]))
      continue;
    const long begin = particles.begin_of(b), end = particles.end_of(b);
    const long n_blocks = (end - begin + block_size - 1) / block_size;
    double viscous = 0.0;
    double max_ratio = 0.0;
    long failed_point = -1;
    std::string message;
#pragma omp parallel reduction(+ : viscous) reduction(max : max_ratio)
    {
      std::vector<materials::PointResponse> responses(block_size);
#pragma omp for schedule(dynamic, 4)
      for (long k = 0; k < n_blocks; ++k)
      {
        const long first = begin + k * block_size;
        const long last = std::min(end, first + block_size);
        try
        {
          viscous += update_range(s, material, s.body_density[b], volumetric_rate, particles,
                                  first, last, responses, max_ratio);
        }
        catch (const std::exception& e)
        {
          // The block failed as a whole: name its first inverted or non-finite point (what
          // the laws refuse), else its first point.
          long bad = first;
          for (long p = first; p < last; ++p)
            if (const double J = particles.deformation_gradient[p].determinant();
                !(J > 0.0) || !std::isfinite(J))
            {
              bad = p;
              break;
            }
#pragma omp critical
          if (failed_point < 0 || bad < failed_point)
          {
            failed_point = bad;
            message = e.what();
          }
        }
      }
    }
    result.viscous_dissipation += viscous;
    result.max_von_mises_over_yield[b] = max_ratio;
    if (failed_point >= 0 && result.failed_point < 0)
    {
      result.failed_point = failed_point;
      result.failure_message = message;
    }
  }
}
} // namespace vulnus::mpm
