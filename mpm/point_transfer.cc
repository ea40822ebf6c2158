// Splitting, flattening and appending point containers.
#include "mpm/point_transfer.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace vulnus::mpm
{
namespace
{
Particles empty_like(const Particles& points)
{
  Particles result;
  result.body_begin.assign(points.n_bodies() + 1, 0);
  return result;
}

template <class T>
void append_bytes(std::vector<char>& bytes, const T* values, const std::size_t n)
{
  const std::size_t offset = bytes.size();
  bytes.resize(offset + sizeof(T) * n);
  if (n > 0)
    std::memcpy(bytes.data() + offset, values, sizeof(T) * n);
}

/// Calls f(a's array, b's matching array) for each per-point array.
template <class F>
void for_each_array_pair(Particles& a, const Particles& b, F&& f)
{
  std::vector<const void*> arrays_of_b;
  b.for_each_array([&arrays_of_b](const auto& values) { arrays_of_b.push_back(&values); });
  std::size_t k = 0;
  a.for_each_array(
    [&](auto& values)
    {
      using Values = std::decay_t<decltype(values)>;
      f(values, *static_cast<const Values*>(arrays_of_b[k++]));
    });
}

class ByteReader
{
public:
  ByteReader(const char* data, const std::size_t size) : data(data), size(size) {}
  template <class T>
  void read(T* values, const std::size_t n)
  {
    if (sizeof(T) * n > size - offset)
      throw std::runtime_error("point transfer: message of " + std::to_string(size) +
                               " bytes is shorter than its contents");
    if (n > 0)
      std::memcpy(static_cast<void*>(values), data + offset, sizeof(T) * n);
    offset += sizeof(T) * n;
  }
  bool at_end() const { return offset == size; }

private:
  const char* data;
  std::size_t size;
  std::size_t offset = 0;
};
} // namespace

std::vector<Particles> split_by_destination(const Particles& points,
                                            const std::vector<int>& destination,
                                            const int n_destinations)
{
  std::vector<std::vector<std::size_t>> chosen(n_destinations);
  std::vector<std::vector<std::size_t>> body_ends(n_destinations);
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
  {
    for (std::size_t p = points.begin_of(b); p < points.end_of(b); ++p)
      chosen[destination[p]].push_back(p);
    for (int d = 0; d < n_destinations; ++d)
      body_ends[d].push_back(chosen[d].size());
  }
  std::vector<Particles> result(n_destinations, empty_like(points));
  for (int d = 0; d < n_destinations; ++d)
  {
    const std::vector<std::size_t>& order = chosen[d];
    for_each_array_pair(result[d], points,
                        [&order](auto& target, const auto& source)
                        {
                          target.resize(order.size());
                          for (std::size_t i = 0; i < order.size(); ++i)
                            target[i] = source[order[i]];
                        });
    for (std::size_t b = 0; b < points.n_bodies(); ++b)
      result[d].body_begin[b + 1] = body_ends[d][b];
  }
  return result;
}

std::vector<char> to_bytes(const Particles& points)
{
  std::vector<char> bytes;
  const std::uint64_t counts[2] = {points.n_bodies(), points.size()};
  append_bytes(bytes, counts, 2);
  append_bytes(bytes, points.body_begin.data(), points.body_begin.size());
  points.for_each_array([&bytes](const auto& values)
                        { append_bytes(bytes, values.data(), values.size()); });
  return bytes;
}

Particles from_bytes(const char* data, const std::size_t size)
{
  ByteReader reader(data, size);
  std::uint64_t counts[2] = {0, 0};
  reader.read(counts, 2);
  if (counts[0] > 1000 || counts[1] > size)
    throw std::runtime_error("point transfer: implausible header");
  Particles points;
  points.body_begin.resize(counts[0] + 1);
  reader.read(points.body_begin.data(), points.body_begin.size());
  points.for_each_array(
    [&](auto& values)
    {
      values.resize(counts[1]);
      reader.read(values.data(), values.size());
    });
  if (!reader.at_end() || points.body_begin.back() != counts[1])
    throw std::runtime_error("point transfer: message size does not match its contents");
  return points;
}

void append_points(Particles& points, const Particles& more)
{
  if (more.size() == 0)
    return;
  if (more.n_bodies() != points.n_bodies())
    throw std::invalid_argument("append_points: containers have different bodies");
  // Interleave body by body: the new order takes each body's old points, then its new ones.
  const std::size_t n_old = points.size();
  std::vector<std::size_t> order;
  order.reserve(n_old + more.size());
  std::vector<std::size_t> new_begin{0};
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
  {
    for (std::size_t p = points.begin_of(b); p < points.end_of(b); ++p)
      order.push_back(p);
    for (std::size_t p = more.begin_of(b); p < more.end_of(b); ++p)
      order.push_back(n_old + p);
    new_begin.push_back(order.size());
  }
  // Concatenate the arrays (old, then new), then reorder into body ranges.
  for_each_array_pair(points, more, [](auto& values, const auto& extra)
                      { values.insert(values.end(), extra.begin(), extra.end()); });
  points.permute(order);
  points.body_begin = new_begin;
}
} // namespace vulnus::mpm
