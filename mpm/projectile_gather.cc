// Gathering the subcycled projectile's points and forces on every rank.
#include "mpm/projectile_gather.h"

#include "mpm/point_transfer.h"

namespace vulnus::mpm
{
namespace
{
std::vector<char> bytes_of(const std::vector<Vector3>& vectors)
{
  const char* first = reinterpret_cast<const char*>(vectors.data());
  return std::vector<char>(first, first + vectors.size() * sizeof(Vector3));
}

void append_vectors(std::vector<Vector3>& out, const std::vector<char>& bytes)
{
  const Vector3* first = reinterpret_cast<const Vector3*>(bytes.data());
  out.insert(out.end(), first, first + bytes.size() / sizeof(Vector3));
}
} // namespace

GatheredProjectile gather_on_every_rank(const RankGroup& ranks, const Particles& mine,
                                        const std::vector<Vector3>& force)
{
  const std::size_t n_ranks = static_cast<std::size_t>(ranks.size());
  const std::vector<std::vector<char>> point_messages =
    ranks.exchange_with_all(std::vector<std::vector<char>>(n_ranks, to_bytes(mine)));
  const std::vector<std::vector<char>> force_messages =
    ranks.exchange_with_all(std::vector<std::vector<char>>(n_ranks, bytes_of(force)));
  GatheredProjectile all;
  std::vector<Particles> shares;
  for (int r = 0; r < ranks.size(); ++r)
  {
    shares.push_back(from_bytes(point_messages[r].data(), point_messages[r].size()));
    if (r < ranks.rank())
      all.first_of_mine += shares.back().size();
    append_vectors(all.force, force_messages[r]);
  }
  Particles none;
  none.body_begin.assign(2, 0);
  all.points = merge_points(none, {}, shares);
  return all;
}
} // namespace vulnus::mpm
