// Initial velocity fields given to the points by a caller (vibration modes, spinning blocks):
// the velocities, and under APIC their affine part as the field's gradient.
#include "mpm/solver.h"

namespace vulnus::mpm
{
void Solver::set_point_velocities(const std::function<Vector3(const Vector3&)>& field,
                                  const int body)
{
  if (rigid_hold.record().held && (body < 0 || body == projectile_body))
  {
    rigid_hold.release("its points were given a velocity field", static_cast<long>(n_steps),
                       current_time);
    make_projectile_deformable();
  }
  // APIC's affine part starts as the field's gradient (central differences), or the first
  // scatter is PIC's; the hoop direction of an axisymmetric grid has none.
  const double step = 1e-3 * grid.cell_size();
  const int n_directions = grid.axisymmetric() ? 2 : 3;
  for (std::size_t b = 0; b < particles.n_bodies(); ++b)
    if (!grid_settings.body_is_rigid[b] && (body < 0 || static_cast<int>(b) == body))
      for (std::size_t p = particles.begin_of(b); p < particles.end_of(b); ++p)
      {
        const Vector3& x = particles.position[p];
        particles.velocity[p] = field(x);
        if (!transfer.affine)
          continue;
        Tensor2 gradient = Tensor2::Zero();
        for (int j = 0; j < n_directions; ++j)
          gradient.col(j) =
            (field(x + step * Vector3::Unit(j)) - field(x - step * Vector3::Unit(j))) / (2 * step);
        if (grid.axisymmetric())
          gradient.row(2).setZero();
        particles.affine_velocity[p] = gradient.cast<float>();
      }
  const SceneDiagnostics d = diagnostics();
  energy_at_start = d.kinetic_energy + d.strain_energy + d.potential_energy;
  momentum_at_start = d.momentum;
}
} // namespace vulnus::mpm
