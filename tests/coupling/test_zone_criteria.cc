// The adaptive zone's criteria on what a far-field cell cannot carry: a block moving rigidly
// past a tenth of a cell converts under the whole-displacement rule and not under the
// non-affine one (rigid motion is affine over every cell); a block sheared uniformly converts
// under the distortion bound and under nothing else; each conversion records which rule
// asked for it.
#include "coupling/hybrid_solver.h"
#include "hybrid_test_scenes.h"

#include <gtest/gtest.h>

namespace vulnus::coupling
{
namespace
{
using testing::block_scene;
using testing::uniform_far_field;
using testing::zone;

/// The 12 mm block with a 4 mm zone in its middle that may grow 2 mm on every side, moving
/// with v = v0 + L X (prescribed on its outer faces, given as the initial velocity: a
/// uniform motion the far field and the zone carry exactly), checked every 10 MPM steps.
std::unique_ptr<HybridSolver> moving_block(const Eigen::Vector3d& v0, const Eigen::Matrix3d& L,
                                           AdaptiveZoneParameters rules)
{
  const double h = 1e-3;
  mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, h);
  s.cfl = 0.1;
  HybridParameters hybrid =
    zone({{0.004, 0.004, 0.004}}, {{0.008, 0.008, 0.008}}, CouplingScheme::multi_step);
  rules.enabled = true;
  rules.reach = 0.002;
  rules.check_interval = 10;
  hybrid.adaptive = rules;
  const HybridScene split = decompose(s, hybrid, uniform_far_field(h));
  auto field = [v0, L](const mpm::Vector3& x) -> mpm::Vector3 { return v0 + L * x; };
  auto solver = std::make_unique<HybridSolver>(split, MPI_COMM_WORLD, [field](fem::FarFieldSolver& fe) {
    for (unsigned int f = 0; f < fem::n_slab_faces; ++f)
      fe.set_face_velocity_field(f, [field](const dealii::Point<3>& X, double) {
        const mpm::Vector3 v = field(mpm::Vector3(X[0], X[1], X[2]));
        return dealii::Tensor<1, 3>({v[0], v[1], v[2]});
      });
  });
  solver->set_initial_velocity(field);
  return solver;
}

std::uint64_t flagged(const HybridSolver& solver, const ZoneCause cause)
{
  std::uint64_t n = 0;
  for (const ZoneConversion& c : solver.conversions())
    n += c.flagged[static_cast<int>(cause)];
  return n;
}

void run_to(HybridSolver& solver, const double t)
{
  while (solver.time() < t)
    solver.advance();
}
} // namespace

// At 1 m/s the block has moved 0.3 mm, 0.3 of a cell, by 0.3 ms.
TEST(ZoneCriteria, RigidMotionConvertsUnderTheWholeDisplacementRuleOnly)
{
  const Eigen::Vector3d v0(1.0, -0.5, 0.0);
  AdaptiveZoneParameters total;
  total.threshold = 1.0;
  total.interface_motion = InterfaceMotion::total;
  auto moved = moving_block(v0, Eigen::Matrix3d::Zero(), total);
  run_to(*moved, 3e-4);
  ASSERT_FALSE(moved->conversions().empty());
  EXPECT_GT(flagged(*moved, ZoneCause::interface_motion), 0u);

  AdaptiveZoneParameters non_affine = total;
  non_affine.interface_motion = InterfaceMotion::non_affine;
  non_affine.distortion = 0.1;
  non_affine.jacobian_ratio = 0.5;
  auto kept = moving_block(v0, Eigen::Matrix3d::Zero(), non_affine);
  run_to(*kept, 3e-4);
  EXPECT_TRUE(kept->conversions().empty());
  EXPECT_NEAR(kept->time_averaged_zone_fraction(), std::pow(4.0 / 12.0, 3), 1e-12);
}

// A simple shear at 1000/s reaches ln(lambda_max / lambda_min) = 0.15 at a shear of 0.15,
// 0.15 ms in; its motion is affine, so only the distortion bound asks for cells.
TEST(ZoneCriteria, AUniformShearConvertsOnTheDistortionBoundOnly)
{
  Eigen::Matrix3d L = Eigen::Matrix3d::Zero();
  L(0, 1) = 1000.0;
  AdaptiveZoneParameters rules;
  rules.threshold = 1.0;
  rules.interface_motion = InterfaceMotion::non_affine;
  rules.distortion = 0.15;
  auto sheared = moving_block(Eigen::Vector3d::Zero(), L, rules);
  run_to(*sheared, 1.3e-4);
  EXPECT_TRUE(sheared->conversions().empty());
  run_to(*sheared, 2e-4);
  ASSERT_FALSE(sheared->conversions().empty());
  EXPECT_GT(flagged(*sheared, ZoneCause::distortion), 0u);
  EXPECT_EQ(flagged(*sheared, ZoneCause::interface_motion), 0u);
  EXPECT_EQ(flagged(*sheared, ZoneCause::failure), 0u);
  EXPECT_GT(sheared->time_averaged_zone_fraction(), std::pow(4.0 / 12.0, 3));
}
} // namespace vulnus::coupling
