// Slab decomposition and point transfer without MPI: balanced cuts, ownership of layers,
// and containers surviving a split, a trip through bytes and a merge unchanged.
#include "mpm/point_transfer.h"
#include "mpm/slab_partition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>

using namespace vulnus;
using mpm::SlabPartition;
using mpm::Vector3;

TEST(SlabPartition, CutsBalanceThePointCount)
{
  // 40 layers, all points in layers 10..29 (20 each): 2 ranks cut at 20, 4 ranks every 5.
  std::vector<std::uint64_t> counts(40, 0);
  for (int l = 10; l < 30; ++l)
    counts[l] = 20;
  const SlabPartition two = SlabPartition::balanced(1, counts, 2);
  EXPECT_EQ(two.axis(), 1);
  EXPECT_EQ(two.first_layers()[1], 20);
  const SlabPartition four = SlabPartition::balanced(1, counts, 4);
  EXPECT_EQ(four.first_layers()[1], 15);
  EXPECT_EQ(four.first_layers()[2], 20);
  EXPECT_EQ(four.first_layers()[3], 25);
  // Ownership: each layer to one rank, the open ends to the end ranks.
  EXPECT_EQ(four.rank_of_layer(-100), 0);
  EXPECT_EQ(four.rank_of_layer(14), 0);
  EXPECT_EQ(four.rank_of_layer(15), 1);
  EXPECT_EQ(four.rank_of_layer(24), 2);
  EXPECT_EQ(four.rank_of_layer(25), 3);
  EXPECT_EQ(four.rank_of_layer(1000), 3);
}

TEST(SlabPartition, SlabsKeepTheMinimumThickness)
{
  // Every point in one layer: the cuts still leave min_layers_per_rank layers to each rank.
  std::vector<std::uint64_t> counts(16, 0);
  counts[7] = 1000;
  const SlabPartition p = SlabPartition::balanced(0, counts, 4);
  const auto& cuts = p.first_layers();
  for (int r = 1; r < 4; ++r)
    EXPECT_EQ(cuts[r], 4 * r);
  // A stencil reaching one layer down and two up touches only the neighbours' nodes.
  const auto [lo, hi] = p.touched_node_layers(1, 1, 2);
  EXPECT_EQ(lo, 3);
  EXPECT_EQ(hi, 9);
  EXPECT_GT(lo, p.touched_node_layers(0, 1, 2).first);
  EXPECT_LT(p.touched_node_layers(0, 1, 2).second, p.touched_node_layers(2, 1, 2).first);
}

TEST(SlabPartition, TooManyRanksForTheGridIsRefused)
{
  const std::vector<std::uint64_t> counts(10, 5);
  try
  {
    SlabPartition::balanced(2, counts, 3);
    FAIL() << "expected an error";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("10 cell layers along axis 2"), std::string::npos) << e.what();
  }
}

TEST(SlabPartition, AxisWithTheMostOccupiedLayers)
{
  const std::vector<std::vector<std::uint64_t>> counts = {{0, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 0}};
  EXPECT_EQ(mpm::choose_slab_axis(counts), 1);
}

namespace
{
mpm::Particles two_bodies()
{
  mpm::Particles p;
  for (int b = 0; b < 2; ++b)
  {
    p.start_body();
    for (int i = 0; i < 5 + 3 * b; ++i)
      p.append(Vector3(i, b, 0.5 * i), Vector3(-i, 2.0 * b, 1), 1.0 + i, 0.1 * (b + 1), Vector3::UnitX(),
               b == 1);
    p.finish_body();
  }
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    p.failure[i] = static_cast<std::uint8_t>(i % 4);
    p.deformation_gradient[i](0, 1) = 0.01 * i;
    p.energy_density[i] = 3.0 * i;
    if (auto* history = p.plastic_of(i))
      history->equivalent_plastic_strain = 0.5 * i;
  }
  return p;
}
} // namespace

TEST(PointTransfer, SplitBytesAndMergeKeepEveryPoint)
{
  const mpm::Particles points = two_bodies();
  std::vector<int> destination(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    destination[i] = static_cast<int>(i % 3);
  const std::vector<mpm::Particles> parts = mpm::split_by_destination(points, destination, 3);
  mpm::Particles merged;
  merged.body_begin.assign(3, 0);
  for (const mpm::Particles& part : parts)
  {
    const std::vector<char> bytes = mpm::to_bytes(part);
    mpm::append_points(merged, mpm::from_bytes(bytes.data(), bytes.size()));
  }
  ASSERT_EQ(merged.size(), points.size());
  EXPECT_EQ(merged.end_of(0), points.end_of(0)); // body ranges survive
  for (std::size_t i = 0; i < merged.size(); ++i)
  {
    const std::uint32_t id = merged.id[i];
    const std::size_t original = id;
    EXPECT_EQ(merged.position[i], points.position[original]);
    EXPECT_EQ(merged.velocity[i], points.velocity[original]);
    EXPECT_EQ(merged.deformation_gradient[i], points.deformation_gradient[original]);
    EXPECT_EQ(merged.failure[i], points.failure[original]);
    EXPECT_EQ(merged.energy_density[i], points.energy_density[original]);
    EXPECT_EQ(merged.mass[i], points.mass[original]);
    EXPECT_EQ(i < merged.end_of(0), original < points.end_of(0));
    ASSERT_EQ(merged.plastic_of(i) != nullptr, i >= merged.end_of(0)); // body 1 only
    if (merged.plastic_of(i))
    {
      EXPECT_EQ(merged.plastic_of(i)->equivalent_plastic_strain, 0.5 * original);
    }
  }
}

namespace
{
/// Bodies of the given sizes; every field of a point is a function of its id. The points of
/// body 1 have a plastic history.
mpm::Particles numbered_points(const std::vector<int>& sizes, std::uint32_t first_id)
{
  mpm::Particles p;
  for (const int n : sizes)
  {
    p.start_body();
    const bool plastic = p.n_bodies() == 2;
    for (int i = 0; i < n; ++i)
    {
      const double id = first_id + p.size();
      p.append(Vector3(id, 0, 0), Vector3(0, id, 0), id, 2 * id, Vector3::UnitZ(), plastic);
      p.id.back() = first_id + static_cast<std::uint32_t>(p.size() - 1);
      p.energy_density.back() = 3 * id;
      if (plastic)
        p.plastic_pool.back().equivalent_plastic_strain = 4 * id;
    }
    p.finish_body();
  }
  return p;
}

/// Ids of each body, sorted.
std::vector<std::vector<std::uint32_t>> ids_by_body(const mpm::Particles& p)
{
  std::vector<std::vector<std::uint32_t>> ids(p.n_bodies());
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
  {
    ids[b].assign(p.id.begin() + p.begin_of(b), p.id.begin() + p.end_of(b));
    std::sort(ids[b].begin(), ids[b].end());
  }
  return ids;
}
} // namespace

// The in-place exchange against the copying merge on random removals and arrivals: bodies
// shrinking, growing, emptying and starting empty, and every field still matching its id.
TEST(PointTransfer, InPlaceExchangeEqualsTheCopyingMerge)
{
  std::srand(7);
  auto random_sizes = [] {
    std::vector<int> sizes(3);
    for (int& n : sizes)
      n = std::rand() % 4 == 0 ? 0 : std::rand() % 40;
    return sizes;
  };
  for (int trial = 0; trial < 500; ++trial)
  {
    const mpm::Particles original = numbered_points(random_sizes(), 0);
    std::vector<char> keep(original.size());
    const int keep_percent = std::rand() % 101;
    for (char& k : keep)
      k = std::rand() % 100 < keep_percent;
    std::vector<mpm::Particles> incoming;
    for (int i = 0, n = std::rand() % 3; i < n; ++i)
      incoming.push_back(numbered_points(random_sizes(), 1000 * (i + 1)));

    const mpm::Particles expected = mpm::merge_points(original, keep, incoming);
    mpm::Particles result = original;
    mpm::exchange_in_place(result, keep, incoming);
    ASSERT_EQ(result.body_begin, expected.body_begin) << "trial " << trial;
    ASSERT_EQ(ids_by_body(result), ids_by_body(expected)) << "trial " << trial;
    result.for_each_array([&](const auto& values) { ASSERT_EQ(values.size(), result.size()); });
    for (std::size_t i = 0; i < result.size(); ++i)
    {
      const double id = result.id[i];
      ASSERT_EQ(result.position[i], Vector3(id, 0, 0)) << "trial " << trial;
      ASSERT_EQ(result.velocity[i], Vector3(0, id, 0));
      ASSERT_EQ(result.mass[i], id);
      ASSERT_EQ(result.reference_volume[i], 2 * id);
      ASSERT_EQ(result.energy_density[i], 3 * id);
      const bool in_plastic_body = result.body_of(i) == 1;
      ASSERT_EQ(result.plastic_of(i) != nullptr, in_plastic_body) << "trial " << trial;
      if (in_plastic_body)
      {
        ASSERT_EQ(result.plastic_of(i)->equivalent_plastic_strain, 4 * id) << "trial " << trial;
      }
    }
  }
}

// Sorting and removing points compact the plastic pool: it then holds exactly the histories
// of the remaining points, in point order.
TEST(PointTransfer, PermuteAndRemovalCompactThePlasticPool)
{
  mpm::Particles p = numbered_points({4, 6, 3}, 0);
  std::vector<std::uint32_t> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<std::uint32_t>(i);
  std::reverse(order.begin() + 4, order.begin() + 10); // reverses body 1
  p.permute(order);
  std::vector<char> keep(p.size(), 1);
  keep[5] = keep[8] = 0;
  p.keep_only(keep);
  ASSERT_EQ(p.plastic_pool.size(), 4u);
  for (std::size_t i = p.begin_of(1); i < p.end_of(1); ++i)
  {
    EXPECT_EQ(p.plastic_slot[i].index, i - p.begin_of(1));
    EXPECT_EQ(p.plastic_of(i)->equivalent_plastic_strain, 4.0 * p.id[i]);
  }
  EXPECT_EQ(p.plastic_of(0), nullptr);
  EXPECT_EQ(p.plastic_of(p.size() - 1), nullptr);
}

TEST(PointTransfer, AMessageReferringToAMissingPlasticHistoryIsRefused)
{
  mpm::Particles p = two_bodies();
  p.plastic_slot.back().index = 1000;
  const std::vector<char> bytes = mpm::to_bytes(p);
  EXPECT_THROW(mpm::from_bytes(bytes.data(), bytes.size()), std::runtime_error);
}

TEST(PointTransfer, ATruncatedMessageIsRefused)
{
  const std::vector<char> bytes = mpm::to_bytes(two_bodies());
  EXPECT_THROW(mpm::from_bytes(bytes.data(), bytes.size() - 8), std::runtime_error);
}
