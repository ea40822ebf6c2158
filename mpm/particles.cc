// Particle arrays: appending and reordering.
#include "mpm/particles.h"

namespace vulnus::mpm
{
void Particles::reserve(const std::size_t n)
{
  for_each_array([n](auto& values) { values.reserve(n); });
}

void Particles::append(const Vector3& x, const Vector3& v, const double m, const double volume,
                       const Vector3& fiber)
{
  id.push_back(static_cast<std::uint32_t>(position.size()));
  position.push_back(x);
  reference_position.push_back(x);
  velocity.push_back(v);
  deformation_gradient.push_back(Tensor2::Identity());
  stress.push_back(Tensor2::Zero());
  mass.push_back(m);
  reference_volume.push_back(volume);
  fiber_direction.push_back(fiber);
  state.emplace_back();
  energy_density.push_back(0.0);
  dissipated_density.push_back(0.0);
  wave_speed.push_back(0.0);
}

namespace
{
template <class T>
void apply_order(std::vector<T>& values, const std::vector<std::size_t>& order)
{
  std::vector<T> reordered(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    reordered[i] = values[order[i]];
  values.swap(reordered);
}
} // namespace

void Particles::keep_only(const std::vector<char>& keep)
{
  std::vector<std::size_t> order;
  order.reserve(size());
  std::vector<std::size_t> new_begin{0};
  for (std::size_t b = 0; b + 1 < body_begin.size(); ++b)
  {
    for (std::size_t p = body_begin[b]; p < body_begin[b + 1]; ++p)
      if (keep[p])
        order.push_back(p);
    new_begin.push_back(order.size());
  }
  permute(order);
  body_begin = new_begin;
}

void Particles::permute(const std::vector<std::size_t>& order)
{
  for_each_array([&order](auto& values) { apply_order(values, order); });
}
} // namespace vulnus::mpm
