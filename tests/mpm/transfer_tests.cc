// Particle-grid transfers split into point shares: which nodes are contested, and the scatter
// and the MUSL momentum projection against a plain serial sum over a dense grid, for shares
// run by teams of any size (more shares than threads, fewer, equal) on unsorted points, where
// most nodes are contested.
#include "mpm/grid_to_particle.h"
#include "mpm/particle_to_grid.h"
#include "mpm/shape_functions.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <map>
#include <random>
#include <set>

using namespace vulnus::mpm;

TEST(GridMarks, ANodeTwoSharesTouchIsContested)
{
  Grid grid(Vector3::Zero(), Vector3(3e-3, 3e-3, 3e-3), 1e-3);
  const std::int64_t alone = grid.node_key(0, 0, 0), both = grid.node_key(1, 0, 0),
                     other = grid.node_key(2, 0, 0);
  grid.mark(alone, 0);
  grid.mark(alone, 0);
  grid.mark(both, 1);
  grid.mark(both, 0);
  grid.mark(both, 1);
  grid.mark(other, 1);
  ASSERT_EQ(grid.number_active_nodes(2), 3u);
  EXPECT_EQ(grid.n_point_shares(), 2);
  ASSERT_EQ(grid.n_contested(), 1u);
  EXPECT_EQ(grid.contested_slots()[0], grid.slot(both));
  EXPECT_EQ(grid.contested_index(grid.slot(both)), 0);
  EXPECT_EQ(grid.contested_index(grid.slot(alone)), -1);
  EXPECT_EQ(grid.contested_index(grid.slot(other)), -1);
  grid.clear_active_nodes();
  EXPECT_EQ(grid.slot(both), -1);
  grid.mark(both, 0);
  grid.number_active_nodes(1);
  EXPECT_EQ(grid.n_contested(), 0u);
}

TEST(PointShares, SharesTileTheRangeInPiecesOfNearlyEqualSize)
{
  for (const long n : {0L, 1L, 7L, 100L, 101L})
    for (const int n_shares : {1, 2, 3, 8})
    {
      long next = 5, smallest = n, largest = 0;
      for (int share = 0; share < n_shares; ++share)
      {
        const ShareRange range = share_of(5, 5 + n, share, n_shares);
        EXPECT_EQ(range.begin, next);
        smallest = std::min(smallest, range.end - range.begin);
        largest = std::max(largest, range.end - range.begin);
        next = range.end;
      }
      EXPECT_EQ(next, 5 + n);
      EXPECT_LE(largest - smallest, 1);
    }
}

namespace
{
struct Scene
{
  Grid grid{Vector3::Zero(), Vector3(6e-3, 6e-3, 6e-3), 1e-3};
  Particles particles;
  TransferSettings transfer;
};

/// Two bodies of random points in random order (so shares interleave in space).
Scene random_scene(const ShapeFunction shape)
{
  Scene s;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(0.2e-3, 5.8e-3), unit(-1.0, 1.0),
      positive(0.5, 1.5);
  for (int b = 0; b < 2; ++b)
  {
    s.particles.start_body();
    for (int p = 0; p < 700; ++p)
    {
      s.particles.append(Vector3(coordinate(random), coordinate(random), coordinate(random)),
                         Vector3(unit(random), unit(random), unit(random)), 1e-3 * positive(random),
                         1e-9 * positive(random), Vector3::UnitX());
      Tensor2& F = s.particles.deformation_gradient.back();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          F(i, j) += 0.1 * unit(random);
      for (int c = 0; c < 6; ++c)
        s.particles.stress.back()[c] = 1e3 * unit(random);
    }
    s.particles.finish_body();
  }
  s.transfer.shape = shape;
  s.transfer.half_size_cells = {0.25, 0.25};
  s.transfer.contact_normals = true;
  return s;
}

/// Weights and gradients of the nodes of x (some may be zero): for linear and GIMP by the
/// tensor product of the 1D functions, for CPDI summed over the corners of the domain of F.
std::map<std::int64_t, std::pair<double, Vector3>>
stencil(const Grid& grid, const ShapeFunction shape, const double lp, const Vector3& x,
        const Tensor2& F)
{
  std::map<std::int64_t, std::pair<double, Vector3>> nodes;
  if (shape == ShapeFunction::cpdi)
  {
    const Tensor2 r = cpdi_half_vectors(F, lp);
    for (int c = 0; c < 8; ++c)
    {
      const Vector3 sign(corner_sign(c, 0), corner_sign(c, 1), corner_sign(c, 2));
      const Vector3 gradient = r.inverse().transpose() * sign / (8.0 * grid.cell_size());
      for (const auto& [key, wg] : stencil(grid, ShapeFunction::linear, 0.0,
                                           x + grid.cell_size() * r * sign, F))
      {
        auto& entry = nodes.try_emplace(key, 0.0, Vector3::Zero()).first->second;
        entry.first += wg.first / 8.0;
        entry.second += wg.first * gradient;
      }
    }
    return nodes;
  }
  const Vector3 s = grid.to_cell_units(x);
  AxisWeights w[3];
  for (int d = 0; d < 3; ++d)
    if (shape == ShapeFunction::linear)
      linear_axis_weights(s[d], grid.inverse_cell_size(), w[d]);
    else
      gimp_axis_weights(s[d], lp, grid.inverse_cell_size(), w[d]);
  const int n = nodes_per_axis(shape);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
      {
        const double weight = w[0].value[i] * w[1].value[j] * w[2].value[k];
        const Vector3 gradient(w[0].derivative[i] * w[1].value[j] * w[2].value[k],
                               w[0].value[i] * w[1].derivative[j] * w[2].value[k],
                               w[0].value[i] * w[1].value[j] * w[2].derivative[k]);
        nodes[grid.node_key(w[0].first_node + i, w[1].first_node + j, w[2].first_node + k)] = {
            weight, gradient};
      }
  return nodes;
}

/// Largest difference of a scattered field (actual(entry)) from the serial sum
/// (reference(dense entry)), over the largest reference value.
template <class Actual, class Reference>
double relative_difference(const Scene& s, const std::vector<NodeBodyData>& expected,
                           const Actual& actual, const Reference& reference)
{
  double worst = 0.0, largest = 0.0;
  for (std::size_t slot = 0; slot < s.grid.n_active(); ++slot)
    for (std::size_t b = 0; b < 2; ++b)
    {
      const Vector3 r = reference(expected[s.grid.active_keys()[slot] * 2 + b]);
      worst = std::max(worst, (actual(slot * 2 + b) - r).norm());
      largest = std::max(largest, r.norm());
    }
  return worst / largest;
}

void check_shares(const ShapeFunction shape, const int n_shares, const int team)
{
  SCOPED_TRACE("shares " + std::to_string(n_shares) + ", team " + std::to_string(team));
  Scene s = random_scene(shape);
  const int max_threads = omp_get_max_threads();
  omp_set_num_threads(n_shares);
  mark_active_nodes(s.particles, s.transfer, s.grid);
  omp_set_num_threads(team);
  ScatterBuffers buffers;
  GridFields fields;
  particles_to_grid(s.particles, s.grid, s.transfer, buffers, fields);

  // Serial reference on every box node.
  std::vector<NodeBodyData> expected(s.grid.n_box_nodes() * 2);
  std::set<std::int64_t> touched;
  for (std::size_t b = 0; b < 2; ++b)
    for (std::size_t p = s.particles.begin_of(b); p < s.particles.end_of(b); ++p)
    {
      const double m = s.particles.mass[p];
      const Tensor2 volume_stress = s.particles.reference_volume[p] *
                                    s.particles.deformation_gradient[p].determinant() *
                                    full_tensor(s.particles.stress[p]);
      for (const auto& [key, wg] : stencil(s.grid, shape, 0.25, s.particles.position[p],
                                           s.particles.deformation_gradient[p]))
      {
        touched.insert(key);
        NodeBodyData& node = expected[key * 2 + b];
        node.mass += wg.first * m;
        node.momentum += wg.first * m * s.particles.velocity[p];
        node.force -= volume_stress * wg.second;
        node.mass_gradient += m * wg.second;
      }
    }
  EXPECT_EQ(s.grid.n_active(), touched.size());
  if (n_shares > 1)
    EXPECT_GT(s.grid.n_contested(), s.grid.n_active() / 2); // random order: mostly seams
  else
    EXPECT_EQ(s.grid.n_contested(), 0u);

  // Sums in another order: a few ulps of the largest entry.
  const auto mass = [](const NodeBodyData& d) { return Vector3(d.mass, 0.0, 0.0); };
  EXPECT_LT(relative_difference(
                s, expected, [&](std::size_t e) { return mass(fields.data[e]); }, mass),
            1e-13);
  for (Vector3 NodeBodyData::*member :
       {&NodeBodyData::momentum, &NodeBodyData::force, &NodeBodyData::mass_gradient})
    EXPECT_LT(relative_difference(
                  s, expected, [&](std::size_t e) { return fields.data[e].*member; },
                  [&](const NodeBodyData& d) { return d.*member; }),
              1e-13);

  // MUSL: pure PIC velocities from a random nodal field, projected back as momenta.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  fields.velocity.assign(fields.data.size(), Vector3::Zero());
  for (Vector3& v : fields.velocity_new)
    v = Vector3(unit(random), unit(random), unit(random));
  KinematicsSettings kinematics;
  kinematics.flip_fraction = 0.0;
  kinematics.body_is_rigid = {0, 0};
  kinematics.rigid_velocity = {Vector3::Zero(), Vector3::Zero()};
  update_point_kinematics(s.grid, s.transfer, kinematics, fields, s.particles, &buffers);
  std::vector<NodeBodyData> projected(expected.size());
  for (std::size_t b = 0; b < 2; ++b)
    for (std::size_t p = s.particles.begin_of(b); p < s.particles.end_of(b); ++p)
    {
      const auto nodes = stencil(s.grid, shape, 0.25, s.particles.position[p],
                                 s.particles.deformation_gradient[p]);
      Vector3 v = Vector3::Zero();
      for (const auto& [key, wg] : nodes)
        v += wg.first * fields.velocity_new[s.grid.slot(key) * 2 + b];
      EXPECT_LT((s.particles.velocity[p] - v).norm(), 1e-14);
      for (const auto& [key, wg] : nodes)
        projected[key * 2 + b].momentum += wg.first * s.particles.mass[p] * v;
    }
  EXPECT_LT(relative_difference(
                s, projected, [&](std::size_t e) { return fields.projected_momentum[e]; },
                [](const NodeBodyData& d) { return d.momentum; }),
            1e-13);
  omp_set_num_threads(max_threads);
}
} // namespace

TEST(PointShares, LinearScatterAndProjectionMatchASerialSum)
{
  for (const auto& [n_shares, team] : {std::pair{1, 1}, {1, 2}, {4, 1}, {4, 2}, {3, 3}})
    check_shares(ShapeFunction::linear, n_shares, team);
}

TEST(PointShares, GimpScatterAndProjectionMatchASerialSum)
{
  for (const auto& [n_shares, team] : {std::pair{1, 1}, {4, 1}, {4, 2}, {2, 2}})
    check_shares(ShapeFunction::gimp, n_shares, team);
}

TEST(PointShares, CpdiScatterAndProjectionMatchASerialSum)
{
  for (const auto& [n_shares, team] : {std::pair{1, 1}, {4, 1}, {4, 2}, {2, 2}, {3, 3}})
    check_shares(ShapeFunction::cpdi, n_shares, team);
}
