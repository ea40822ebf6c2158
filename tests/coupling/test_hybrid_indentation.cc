// A slow indentation of a slab by a rigid punch (no failure): the displacement of the MPM
// zone's points in the hybrid run against the same points of the pure-MPM run of the same
// scene, for both coupling schemes. Under mpirun both runs are distributed and compared on
// rank 0 with every rank's points.
#include "coupling/hybrid_solver.h"
#include "hybrid_test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>

namespace vulnus::coupling
{
namespace
{
using testing::indentation_scene;
using testing::zone;

using Displacements = std::map<std::array<long, 3>, mpm::Vector3>;

/// Displacement of the slab's points inside the zone, keyed by reference position (0.1 um).
Displacements zone_displacements(const mpm::Particles& p, const HybridParameters& z)
{
  Displacements u;
  for (std::size_t i = p.begin_of(0); i < p.end_of(0); ++i)
  {
    const mpm::Vector3 X = p.reference_position[i].cast<double>();
    bool inside = true;
    for (int d = 0; d < 3; ++d)
      inside = inside && X[d] > z.zone_min[d] && X[d] < z.zone_max[d];
    if (inside)
      u[{std::lround(X[0] * 1e7), std::lround(X[1] * 1e7), std::lround(X[2] * 1e7)}] =
        p.position[i] - X;
  }
  return u;
}

class HybridIndentation : public ::testing::TestWithParam<CouplingScheme>
{
};

TEST_P(HybridIndentation, DisplacementsMatchThePureMpmRun)
{
  const mpm::SceneParameters scene = indentation_scene();
  const HybridParameters z = zone({-0.006, 0.0, -0.006}, {0.006, 0.01, 0.006}, GetParam());

  mpm::Solver pure(scene, MPI_COMM_WORLD);
  while (!pure.finished())
    pure.advance();
  const Displacements reference = zone_displacements(pure.gather_points(), z);

  fem::FeSceneParameters far_field = testing::uniform_far_field(1e-3);
  far_field.far_cell_size = 2e-3;
  far_field.grading_ratio = 1.5;
  HybridSolver hybrid(decompose(scene, z, far_field), MPI_COMM_WORLD);
  while (!hybrid.finished())
    hybrid.advance();
  const Displacements result = zone_displacements(hybrid.mpm().gather_points(), z);
  if (hybrid.mpm().rank_group().rank() != 0)
    return;

  ASSERT_EQ(result.size(), reference.size());
  ASSERT_GT(result.size(), 1000u);
  double difference = 0.0, norm = 0.0, deepest = 0.0;
  for (const auto& [key, u] : reference)
  {
    const auto it = result.find(key);
    ASSERT_NE(it, result.end());
    difference += (it->second - u).squaredNorm();
    norm += u.squaredNorm();
    deepest = std::max(deepest, u[1]);
  }
  const double relative = std::sqrt(difference / norm);
  std::cout << "indentation: relative L2 difference hybrid vs pure MPM " << relative
            << ", deepest point displacement " << deepest * 1e3 << " mm, FE steps "
            << hybrid.ledger().fe_steps << ", MPM steps " << hybrid.ledger().mpm_steps << '\n';
  EXPECT_GT(deepest, 0.5e-3); // the punch went 1 mm in
  EXPECT_LT(relative, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Schemes, HybridIndentation,
                         ::testing::Values(CouplingScheme::same_step, CouplingScheme::multi_step),
                         [](const ::testing::TestParamInfo<CouplingScheme>& info) {
                           return std::string(info.param == CouplingScheme::same_step
                                                ? "same_step"
                                                : "multi_step");
                         });
} // namespace
} // namespace vulnus::coupling
