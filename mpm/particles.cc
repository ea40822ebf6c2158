// Particle arrays: appending and reordering.
#include "mpm/particles.h"

#include <cmath>

namespace vulnus::mpm
{
void Particles::reserve(const std::size_t n, const std::size_t n_plastic)
{
  for_each_array([n](auto& values) { values.reserve(n); });
  plastic_pool.reserve(n_plastic);
}

void Particles::append(const Vector3& x, const Vector3& v, const double m, const double volume,
                       const Vector3& fiber, const bool plastic_history)
{
  id.push_back(static_cast<std::uint32_t>(position.size()));
  position.push_back(x);
  reference_position.push_back(x.cast<float>());
  velocity.push_back(v);
  affine_velocity.push_back(Eigen::Matrix3f::Zero());
  deformation_gradient.push_back(Tensor2::Identity());
  stress.push_back(SymmetricTensor::Zero());
  mass.push_back(m);
  reference_volume.push_back(volume);
  fiber_direction.push_back(fiber.cast<float>());
  failure.push_back(materials::intact);
  plastic_slot.emplace_back();
  if (plastic_history)
  {
    plastic_slot.back().index = static_cast<std::uint32_t>(plastic_pool.size());
    plastic_pool.emplace_back();
  }
  energy_density.push_back(0.0);
  dissipated_density.push_back(0.0);
  wave_speed.push_back(0.0);
  domain.push_back(Eigen::Matrix3f::Identity() * static_cast<float>(0.5 * std::cbrt(volume)));
}

Particles Particles::copy_of_range(const std::size_t begin, const std::size_t end) const
{
  Particles part;
  part.for_each_array_with(*this, [&](auto& mine, const auto& theirs)
                           { mine.assign(theirs.begin() + begin, theirs.begin() + end); });
  part.body_begin = {0, end - begin};
  for (materials::PlasticSlot& slot : part.plastic_slot)
    if (slot.index != materials::PlasticSlot::none)
    {
      part.plastic_pool.push_back(plastic_pool[slot.index]);
      slot.index = static_cast<std::uint32_t>(part.plastic_pool.size() - 1);
    }
  return part;
}

void Particles::insert_into_body(const std::size_t b, const Particles& added)
{
  const std::size_t at = end_of(b);
  const std::size_t n = added.size();
  const std::size_t pool_offset = plastic_pool.size();
  for_each_array_with(added, [&](auto& mine, const auto& theirs)
                      { mine.insert(mine.begin() + at, theirs.begin(), theirs.end()); });
  for (std::size_t i = at; i < at + n; ++i)
    if (plastic_slot[i].index != materials::PlasticSlot::none)
      plastic_slot[i].index += static_cast<std::uint32_t>(pool_offset);
  plastic_pool.insert(plastic_pool.end(), added.plastic_pool.begin(), added.plastic_pool.end());
  for (std::size_t c = b + 1; c < body_begin.size(); ++c)
    body_begin[c] += n;
}

void Particles::write_back_body(const std::size_t b, const Particles& part)
{
  const std::size_t begin = begin_of(b);
  for (std::size_t i = 0; i < part.size(); ++i)
    if (const materials::PlasticHistory* history = part.plastic_of(i))
      plastic_pool[plastic_slot[begin + i].index] = *history;
  // The slots keep pointing into this container's pool.
  const std::vector<materials::PlasticSlot> slots(plastic_slot.begin() + begin,
                                                  plastic_slot.begin() + begin + part.size());
  for_each_array_with(part, [&](auto& mine, const auto& theirs)
                      { std::copy(theirs.begin(), theirs.end(), mine.begin() + begin); });
  std::copy(slots.begin(), slots.end(), plastic_slot.begin() + begin);
}

namespace
{
/// values[i] = old values[order[i]] by following the permutation's cycles: one element of
/// scratch instead of a second copy of the array.
template <class T>
void apply_order_in_place(std::vector<T>& values, const std::vector<std::uint32_t>& order,
                          std::vector<char>& done)
{
  done.assign(values.size(), 0);
  for (std::size_t start = 0; start < values.size(); ++start)
  {
    if (done[start])
      continue;
    done[start] = 1;
    if (order[start] == start)
      continue;
    T first = std::move(values[start]);
    std::size_t i = start;
    for (std::size_t next = order[i]; next != start; next = order[i])
    {
      values[i] = std::move(values[next]);
      done[next] = 1;
      i = next;
    }
    values[i] = std::move(first);
  }
}
} // namespace

void Particles::keep_only(const std::vector<char>& keep)
{
  // Stable compaction in place: the kept points move down, body by body.
  std::vector<std::size_t> new_begin{0};
  std::size_t kept = 0;
  for (std::size_t b = 0; b + 1 < body_begin.size(); ++b)
  {
    for (std::size_t p = body_begin[b]; p < body_begin[b + 1]; ++p)
      kept += keep[p] != 0;
    new_begin.push_back(kept);
  }
  for_each_array(
    [&keep](auto& values)
    {
      std::size_t w = 0;
      for (std::size_t p = 0; p < values.size(); ++p)
        if (keep[p])
          values[w++] = values[p];
      values.resize(w);
    });
  body_begin = new_begin;
  compact_plastic_pool();
}

void Particles::permute(const std::vector<std::uint32_t>& order)
{
  std::vector<char> done;
  for_each_array([&](auto& values) { apply_order_in_place(values, order, done); });
  compact_plastic_pool();
}

void Particles::compact_plastic_pool()
{
  if (plastic_pool.empty())
    return; // no point has a slot
  std::size_t n_live = 0;
  for (const materials::PlasticSlot& slot : plastic_slot)
    n_live += slot.index != materials::PlasticSlot::none;
  std::vector<materials::PlasticHistory> compacted;
  compacted.reserve(n_live);
  for (materials::PlasticSlot& slot : plastic_slot)
    if (slot.index != materials::PlasticSlot::none)
    {
      compacted.push_back(plastic_pool[slot.index]);
      slot.index = static_cast<std::uint32_t>(compacted.size() - 1);
    }
  plastic_pool = std::move(compacted);
}

long Particles::body_with_invalid_plastic_slots(
  const std::vector<char>* body_has_plastic_history) const
{
  for (std::size_t b = 0; b < n_bodies(); ++b)
    for (std::size_t p = begin_of(b); p < end_of(b); ++p)
    {
      const std::uint32_t slot = plastic_slot[p].index;
      const bool has_slot = slot != materials::PlasticSlot::none;
      if ((has_slot && slot >= plastic_pool.size()) ||
          (body_has_plastic_history && has_slot != ((*body_has_plastic_history)[b] != 0)))
        return static_cast<long>(b);
    }
  return -1;
}
} // namespace vulnus::mpm
