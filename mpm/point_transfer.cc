// Splitting, flattening and merging point containers.
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
template <class T>
void append_bytes(std::vector<char>& bytes, const T* values, const std::size_t n)
{
  const std::size_t offset = bytes.size();
  bytes.resize(offset + sizeof(T) * n);
  if (n > 0)
    std::memcpy(bytes.data() + offset, values, sizeof(T) * n);
}

/// A point of one of several source containers.
struct PointPick
{
  std::size_t source;
  std::size_t index;
};

/// The picked points, in pick order, as one container with the given body ranges: one pass
/// over each array.
Particles gather(const std::vector<const Particles*>& sources, const std::vector<PointPick>& picks,
                 std::vector<std::size_t> body_begin)
{
  // The arrays of every source, by their position in the visiting order.
  std::vector<std::vector<const void*>> arrays(sources.size());
  for (std::size_t i = 0; i < sources.size(); ++i)
    sources[i]->for_each_array([&](const auto& values) { arrays[i].push_back(&values); });
  Particles result;
  std::size_t k = 0;
  result.for_each_array(
    [&](auto& values)
    {
      using Values = std::decay_t<decltype(values)>;
      values.resize(picks.size());
      for (std::size_t i = 0; i < picks.size(); ++i)
        values[i] = (*static_cast<const Values*>(arrays[picks[i].source][k]))[picks[i].index];
      ++k;
    });
  result.body_begin = std::move(body_begin);
  return result;
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
  std::vector<std::vector<PointPick>> picks(n_destinations);
  std::vector<std::vector<std::size_t>> body_begin(n_destinations, std::vector<std::size_t>{0});
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
  {
    for (std::size_t p = points.begin_of(b); p < points.end_of(b); ++p)
      if (destination[p] >= 0)
        picks[destination[p]].push_back({0, p});
    for (int d = 0; d < n_destinations; ++d)
      body_begin[d].push_back(picks[d].size());
  }
  std::vector<Particles> result;
  for (int d = 0; d < n_destinations; ++d)
    result.push_back(gather({&points}, picks[d], body_begin[d]));
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

Particles merge_points(const Particles& points, const std::vector<char>& keep,
                       const std::vector<Particles>& incoming)
{
  std::vector<const Particles*> sources{&points};
  for (const Particles& more : incoming)
  {
    if (more.size() > 0 && more.n_bodies() != points.n_bodies())
      throw std::invalid_argument("merge_points: containers have different bodies");
    sources.push_back(&more);
  }
  std::vector<PointPick> picks;
  std::vector<std::size_t> body_begin{0};
  for (std::size_t b = 0; b < points.n_bodies(); ++b)
  {
    for (std::size_t p = points.begin_of(b); p < points.end_of(b); ++p)
      if (keep[p])
        picks.push_back({0, p});
    for (std::size_t i = 1; i < sources.size(); ++i)
      if (sources[i]->size() > 0)
        for (std::size_t p = sources[i]->begin_of(b); p < sources[i]->end_of(b); ++p)
          picks.push_back({i, p});
    body_begin.push_back(picks.size());
  }
  return gather(sources, picks, std::move(body_begin));
}

void append_points(Particles& points, const Particles& more)
{
  if (more.size() == 0)
    return;
  points = merge_points(points, std::vector<char>(points.size(), 1), {more});
}
} // namespace vulnus::mpm
