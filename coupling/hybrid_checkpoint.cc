// Binary save and restore of a hybrid run: the MPM zone, the far field, then the coupling's
// own state between steps.
#include "coupling/hybrid_solver.h"
#include "mpm/binary_io.h"

namespace vulnus::coupling
{
namespace binary = mpm::binary;

namespace
{
constexpr char tag[8] = {'V', 'U', 'L', 'H', 'Y', 'B', 'R', '1'};
} // namespace

void HybridSolver::save(std::ostream& out) const
{
  mpm_solver->save(out);
  fe_solver->save(out);
  out.write(tag, sizeof(tag));
  binary::put(out, static_cast<std::uint64_t>(keys.size()));
  binary::put(out, window_start);
  binary::put(out, window_end);
  binary::put(out, static_cast<std::uint8_t>(window_open));
  for (const std::vector<mpm::Vector3>* v : {&velocity_start, &velocity_end, &created, &correction})
    binary::put_vector(out, *v);
  binary::put(out, book);
  out.write(tag, sizeof(tag));
  if (!out)
    throw std::runtime_error("hybrid checkpoint could not be written");
}

void HybridSolver::restore(std::istream& in)
{
  mpm_solver->restore(in);
  fe_solver->restore(in);
  binary::expect_tag(in, tag, "not a vulnus hybrid checkpoint (bad coupling header)");
  std::uint64_t n_keys = 0;
  binary::get(in, n_keys);
  if (n_keys != keys.size())
    throw std::runtime_error("hybrid checkpoint has " + std::to_string(n_keys) +
                             " interface nodes, the scene " + std::to_string(keys.size()));
  binary::get(in, window_start);
  binary::get(in, window_end);
  std::uint8_t open = 0;
  binary::get(in, open);
  window_open = open != 0;
  for (std::vector<mpm::Vector3>* v : {&velocity_start, &velocity_end, &created, &correction})
  {
    binary::get_vector(in, *v);
    if (v->size() != keys.size())
      throw std::runtime_error("hybrid checkpoint is inconsistent (interface vectors)");
  }
  binary::get(in, book);
  binary::expect_tag(in, tag, "hybrid checkpoint is incomplete (no trailer)");
}
} // namespace vulnus::coupling
