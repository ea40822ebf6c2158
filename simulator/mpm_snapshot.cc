// Snapshot of the MPM points for output.
#include "simulator/mpm_snapshot.h"

#include <algorithm>

namespace vulnus::simulator
{
io::Snapshot mpm_snapshot(const mpm::Solver& solver)
{
  using Kind = io::Snapshot::FieldKind;
  const mpm::Particles& p = solver.points();
  const std::size_t n = p.size();
  io::Snapshot s(n);
  // Arrays are borrowed and derived fields computed while writing (no memory per point): the
  // snapshot is written before the solver steps again.
  s.borrow_positions(n ? p.position[0].data() : nullptr);
  s.borrow_vector("velocity", n ? p.velocity[0].data() : nullptr);
  s.borrow_symmetric_tensor("stress", n ? p.stress[0].data() : nullptr);
  s.borrow_integer("failure", n ? p.failure.data() : nullptr);
  s.compute("fiber_direction", Kind::vector,
            [&p, &solver](std::size_t first, std::size_t count, void* out) {
              auto* fiber = static_cast<double*>(out);
              for (std::size_t i = 0; i < count; ++i)
              {
                const std::size_t k = first + i;
                mpm::Vector3 a = mpm::Vector3::Zero();
                if (solver.body_material(p.body_of(k)).uses_fibers())
                {
                  a = p.deformation_gradient[k] * p.fiber_direction[k].cast<double>();
                  const double norm = a.norm();
                  a = norm > 0 ? mpm::Vector3(a / norm) : mpm::Vector3::Zero();
                }
                std::copy(a.data(), a.data() + 3, fiber + 3 * i);
              }
            });
  s.compute("material_id", Kind::integer, [&p](std::size_t first, std::size_t count, void* out) {
    auto* body = static_cast<std::int32_t*>(out);
    for (std::size_t i = 0; i < count; ++i)
      body[i] = static_cast<std::int32_t>(p.body_of(first + i));
  });
  s.borrow_integer("id", n ? p.id.data() : nullptr);
  s.compute("equivalent_plastic_strain", Kind::scalar,
            [&p](std::size_t first, std::size_t count, void* out) {
              auto* plastic = static_cast<double*>(out);
              for (std::size_t i = 0; i < count; ++i)
              {
                const materials::PlasticHistory* history = p.plastic_of(first + i);
                plastic[i] = history ? history->equivalent_plastic_strain : 0.0;
              }
            });
  s.borrow_vector("reference_position", n ? p.reference_position[0].data() : nullptr);
  s.compute("displacement", Kind::vector, [&p](std::size_t first, std::size_t count, void* out) {
    auto* u = static_cast<double*>(out);
    for (std::size_t i = 0; i < count; ++i)
      for (int c = 0; c < 3; ++c)
        u[3 * i + c] = p.position[first + i][c] - p.reference_position[first + i][c];
  });
  const std::int32_t rank = solver.rank_group().rank();
  s.compute("rank", Kind::integer, [rank](std::size_t, std::size_t count, void* out) {
    std::fill_n(static_cast<std::int32_t*>(out), count, rank);
  });
  return s;
}
} // namespace vulnus::simulator
