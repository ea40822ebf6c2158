// Snapshot of the MPM points for output.
#include "app/mpm_snapshot.h"

namespace vulnus::app
{
ParticleSnapshot mpm_snapshot(const mpm::Solver& solver)
{
  const mpm::Particles& p = solver.points();
  const std::size_t n = p.size();
  ParticleSnapshot s(n);
  // The solver's arrays are borrowed, not copied: the snapshot is written before the next step.
  s.borrow_positions(n ? p.position[0].data() : nullptr);
  s.borrow_vector("velocity", n ? p.velocity[0].data() : nullptr);
  s.borrow_symmetric_tensor("stress", n ? p.stress[0].data() : nullptr);
  std::vector<std::int32_t> flags(n), body(n), ids(n);
  std::vector<double> fiber(3 * n), plastic(n);
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
    for (std::size_t i = p.begin_of(b); i < p.end_of(b); ++i)
    {
      body[i] = static_cast<std::int32_t>(b);
      flags[i] = p.state[i].failure;
      ids[i] = static_cast<std::int32_t>(p.id[i]);
      plastic[i] = p.state[i].equivalent_plastic_strain;
      mpm::Vector3 a = mpm::Vector3::Zero();
      if (solver.body_material(b).uses_fibers())
      {
        a = p.deformation_gradient[i] * p.fiber_direction[i];
        const double norm = a.norm();
        a = norm > 0 ? mpm::Vector3(a / norm) : mpm::Vector3::Zero();
      }
      for (int d = 0; d < 3; ++d)
        fiber[3 * i + d] = a[d];
    }
  s.add_integer("failure", flags.data());
  s.add_vector("fiber_direction", fiber.data());
  s.add_integer("material_id", body.data());
  s.add_integer("id", ids.data());
  s.add_scalar("equivalent_plastic_strain", plastic.data());
  s.borrow_vector("reference_position", n ? p.reference_position[0].data() : nullptr);
  return s;
}
} // namespace vulnus::app
