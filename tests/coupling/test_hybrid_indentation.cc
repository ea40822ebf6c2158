// A slow indentation of a slab by a rigid punch (no failure): the displacement of the MPM
// zone's points in the hybrid run against the same points of the pure-MPM run of the same
// scene, for both coupling schemes.
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
using testing::zone;

/// Slab [-10, 10] x [0, 10] x [-10, 10] mm on a fixed back face (y+), rollers on the sides;
/// a rigid 6 x 2 x 6 mm punch pushed into the front face at 1 m/s (Mach 0.07) for 1 ms.
mpm::SceneParameters indentation_scene()
{
  const double h = 1e-3;
  mpm::SceneParameters s = testing::block_scene({-0.01, -0.004, -0.01}, {0.01, 0.01, 0.01}, h);
  s.bodies[0].box_min = {-0.01, 0.0, -0.01};
  s.bodies[0].name = "slab";
  s.domain_faces = {mpm::FaceCondition::roller, mpm::FaceCondition::roller,
                    mpm::FaceCondition::free,   mpm::FaceCondition::fixed,
                    mpm::FaceCondition::roller, mpm::FaceCondition::roller};
  materials::MaterialParameters rigid;
  rigid.model = "rigid";
  s.materials.push_back({"punch", rigid});
  mpm::BodyParameters punch;
  punch.name = "punch";
  punch.material = "punch";
  punch.box_min = {-0.003, -0.002, -0.003};
  punch.box_max = {0.003, 0.0, 0.003};
  punch.density = 8000.0;
  punch.initial_velocity = {0.0, 1.0, 0.0};
  punch.rigid_motion = mpm::RigidMotion::prescribed;
  s.bodies.push_back(punch);
  s.contact.enabled = true;
  s.contact.friction_coefficient = -1.0; // no slip under the punch
  s.end_time = 1e-3;
  return s;
}

using Displacements = std::map<std::array<long, 3>, mpm::Vector3>;

/// Displacement of the slab's points inside the zone, keyed by reference position (0.1 um).
Displacements zone_displacements(const mpm::Particles& p, const HybridParameters& z)
{
  Displacements u;
  for (std::size_t i = p.begin_of(0); i < p.end_of(0); ++i)
  {
    const mpm::Vector3& X = p.reference_position[i];
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

  mpm::Solver pure(scene);
  while (!pure.finished())
    pure.advance();
  const Displacements reference = zone_displacements(pure.points(), z);

  fem::FeSceneParameters far_field = testing::uniform_far_field(1e-3);
  far_field.far_cell_size = 2e-3;
  far_field.grading_ratio = 1.5;
  HybridSolver hybrid(decompose(scene, z, far_field), MPI_COMM_WORLD);
  while (!hybrid.finished())
    hybrid.advance();
  const Displacements result = zone_displacements(hybrid.mpm().points(), z);

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
