// Splitting, flattening and merging point containers.
#include "mpm/point_transfer.h"

#include <algorithm>
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
  // The plastic histories follow their points into the result's own pool.
  for (std::size_t i = 0; i < picks.size(); ++i)
  {
    materials::PlasticSlot& slot = result.plastic_slot[i];
    if (slot.index == materials::PlasticSlot::none)
      continue;
    result.plastic_pool.push_back(sources[picks[i].source]->plastic_pool[slot.index]);
    slot.index = static_cast<std::uint32_t>(result.plastic_pool.size() - 1);
  }
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
  const std::uint64_t counts[3] = {points.n_bodies(), points.size(), points.plastic_pool.size()};
  append_bytes(bytes, counts, 3);
  append_bytes(bytes, points.body_begin.data(), points.body_begin.size());
  points.for_each_array([&bytes](const auto& values)
                        { append_bytes(bytes, values.data(), values.size()); });
  append_bytes(bytes, points.plastic_pool.data(), points.plastic_pool.size());
  return bytes;
}

Particles from_bytes(const char* data, const std::size_t size)
{
  ByteReader reader(data, size);
  std::uint64_t counts[3] = {0, 0, 0};
  reader.read(counts, 3);
  if (counts[0] > 1000 || counts[1] > size || counts[2] > size)
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
  points.plastic_pool.resize(counts[2]);
  reader.read(points.plastic_pool.data(), points.plastic_pool.size());
  if (!reader.at_end() || points.body_begin.back() != counts[1])
    throw std::runtime_error("point transfer: message size does not match its contents");
  if (points.body_with_invalid_plastic_slots() >= 0)
    throw std::runtime_error("point transfer: a point refers to a missing plastic history");
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

namespace
{
/// One element copy applied to every array: from `source` (0: the container itself, i > 0:
/// incoming[i - 1]) at `from` to the container at `to`. Copies run in list order.
struct ElementCopy
{
  std::size_t source;
  std::size_t from;
  std::size_t to;
};

/// Copies that turn body b's range [begin, begin + size) into a hole-free range
/// [begin, begin + compacted) in place: holes take the incoming points first, then the last
/// kept points of the body. Returns the incoming points left over (appended later).
std::vector<PointPick> fill_holes(std::size_t begin, std::size_t size,
                                  const std::vector<char>& keep, std::vector<PointPick> arrivals,
                                  std::vector<ElementCopy>& copies, std::size_t& compacted)
{
  std::vector<std::size_t> holes;
  for (std::size_t p = begin; p < begin + size; ++p)
    if (!keep[p])
      holes.push_back(p);
  const std::size_t filled = std::min(holes.size(), arrivals.size());
  for (std::size_t k = 0; k < filled; ++k)
    copies.push_back({arrivals[k].source, arrivals[k].index, holes[k]});
  compacted = size - holes.size() + filled;
  std::size_t last = begin + size; // one past the candidate kept point at the end
  for (std::size_t k = filled; k < holes.size(); ++k)
  {
    while (last > holes[k] + 1 && !keep[last - 1])
      --last;
    if (last <= holes[k] + 1)
      break; // the remaining holes are the body's tail
    --last;
    copies.push_back({0, last, holes[k]});
  }
  arrivals.erase(arrivals.begin(), arrivals.begin() + static_cast<std::ptrdiff_t>(filled));
  return arrivals;
}

/// Copies that move a hole-free range of `count` points from `from` to `to`, moving at most
/// |to - from| points (the range's order rotates). The destination slots outside the old
/// range must be free.
void shift_range(const std::size_t from, const std::size_t to, const std::size_t count,
                 std::vector<ElementCopy>& copies)
{
  if (to == from || count == 0)
    return;
  const std::size_t distance = to > from ? to - from : from - to;
  if (distance >= count)
  {
    for (std::size_t k = 0; k < count; ++k)
      copies.push_back({0, from + k, to + k});
    return;
  }
  if (to < from) // the tail fills the free slots in front
    for (std::size_t k = 0; k < distance; ++k)
      copies.push_back({0, from + count - distance + k, to + k});
  else // the head fills the free slots behind
    for (std::size_t k = 0; k < distance; ++k)
      copies.push_back({0, from + k, from + count + k});
}
} // namespace

void exchange_in_place(Particles& points, const std::vector<char>& keep,
                       const std::vector<Particles>& incoming)
{
  const std::size_t n_bodies = points.n_bodies();
  std::vector<std::vector<PointPick>> arrivals(n_bodies);
  for (std::size_t i = 0; i < incoming.size(); ++i)
  {
    if (incoming[i].size() == 0)
      continue;
    if (incoming[i].n_bodies() != n_bodies)
      throw std::invalid_argument("exchange_in_place: containers have different bodies");
    for (std::size_t b = 0; b < n_bodies; ++b)
      for (std::size_t p = incoming[i].begin_of(b); p < incoming[i].end_of(b); ++p)
        arrivals[b].push_back({i + 1, p});
  }

  std::vector<ElementCopy> copies;
  std::vector<std::size_t> compacted(n_bodies);
  std::vector<std::vector<PointPick>> extra(n_bodies);
  std::vector<std::size_t> new_begin{0};
  for (std::size_t b = 0; b < n_bodies; ++b)
  {
    extra[b] = fill_holes(points.begin_of(b), points.end_of(b) - points.begin_of(b), keep,
                          std::move(arrivals[b]), copies, compacted[b]);
    new_begin.push_back(new_begin.back() + compacted[b] + extra[b].size());
  }
  // Bodies moving to lower indices go first, in order, then those moving up, in reverse:
  // each move then writes only into slots no unmoved body still occupies.
  for (std::size_t b = 0; b < n_bodies; ++b)
    if (new_begin[b] <= points.begin_of(b))
      shift_range(points.begin_of(b), new_begin[b], compacted[b], copies);
  for (std::size_t b = n_bodies; b-- > 0;)
    if (new_begin[b] > points.begin_of(b))
      shift_range(points.begin_of(b), new_begin[b], compacted[b], copies);
  for (std::size_t b = 0; b < n_bodies; ++b)
    for (std::size_t k = 0; k < extra[b].size(); ++k)
      copies.push_back({extra[b][k].source, extra[b][k].index, new_begin[b] + compacted[b] + k});

  const std::size_t n_new = new_begin.back();
  std::vector<std::vector<const void*>> sources(incoming.size());
  for (std::size_t i = 0; i < incoming.size(); ++i)
    incoming[i].for_each_array([&](const auto& values) { sources[i].push_back(&values); });
  std::size_t k = 0;
  points.for_each_array(
    [&](auto& values)
    {
      using Values = std::decay_t<decltype(values)>;
      values.resize(std::max(values.size(), n_new));
      for (const ElementCopy& c : copies)
      {
        values[c.to] = c.source == 0
                         ? values[c.from]
                         : (*static_cast<const Values*>(sources[c.source - 1][k]))[c.from];
        // An arrival brings its plastic history into the pool as it lands (later copies in
        // the list may move it again).
        if constexpr (std::is_same_v<Values, std::vector<materials::PlasticSlot>>)
          if (c.source != 0 && values[c.to].index != materials::PlasticSlot::none)
          {
            points.plastic_pool.push_back(incoming[c.source - 1].plastic_pool[values[c.to].index]);
            values[c.to].index = static_cast<std::uint32_t>(points.plastic_pool.size() - 1);
          }
      }
      values.resize(n_new);
      ++k;
    });
  points.body_begin = std::move(new_begin);
}

void append_points(Particles& points, const Particles& more)
{
  if (more.size() == 0)
    return;
  exchange_in_place(points, std::vector<char>(points.size(), 1), {more});
}
} // namespace vulnus::mpm
