// Checkpoint and restart of the MPM solver: a restored run continues bit for bit, and
// truncated or foreign checkpoints are refused.
#include "mpm/solver.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

using namespace vulnus;
using mpm::Vector3;

namespace
{
/// A ball hitting a gel slab; the ball is rigid or (plastic_ball) a soft elastic-plastic
/// metal that yields at the impact.
mpm::SceneParameters impact_scene(const bool plastic_ball = false)
{
  mpm::SceneParameters scene = test::empty_scene(Vector3(-8e-3, -8e-3, -8e-3), Vector3(8e-3, 14e-3, 8e-3), 1e-3);
  mpm::NamedMaterial gel = test::elastic_material("gel", 2e5, 2.1e3);
  gel.parameters.tissue.failure.enabled = true;
  scene.materials.push_back(gel);
  mpm::NamedMaterial steel = test::rigid_material("steel");
  if (plastic_ball)
  {
    steel.parameters.model = "elastic plastic";
    steel.parameters.elastic_plastic = {1e8, 5e7, 1e5, 1e5};
  }
  scene.materials.push_back(steel);
  scene.bodies.push_back(test::box_body("slab", "gel", Vector3(-8e-3, 0, -8e-3), Vector3(8e-3, 4e-3, 8e-3), 1060.0, 2));
  mpm::BodyParameters ball = test::sphere_body("ball", "steel", Vector3(0, -3e-3, 0), 2.5e-3, 8930.0, 2);
  ball.initial_velocity = Vector3(0, 60, 0);
  ball.is_projectile = true;
  scene.bodies.push_back(ball);
  scene.sort_interval = 7; // a sort falls between the checkpoint and the end
  return scene;
}
} // namespace

class MpmCheckpointBall : public ::testing::TestWithParam<bool>
{
};

// With a rigid ball, and with an elastic-plastic one whose plastic histories (kept only for
// its points, in a pool) must survive the checkpoint and the sorts before and after it.
TEST_P(MpmCheckpointBall, RestoredRunContinuesBitForBit)
{
  const bool plastic_ball = GetParam();
  const mpm::SceneParameters scene = impact_scene(plastic_ball);
  mpm::Solver reference(scene);
  for (int i = 0; i < 20; ++i)
    reference.advance();
  std::stringstream checkpoint;
  reference.save(checkpoint);
  for (int i = 0; i < 25; ++i)
    reference.advance();

  mpm::Solver restarted(scene);
  restarted.restore(checkpoint);
  EXPECT_EQ(restarted.step_count(), 20u);
  for (int i = 0; i < 25; ++i)
    restarted.advance();

  ASSERT_EQ(reference.points().size(), restarted.points().size());
  double most_plastic = 0.0;
  EXPECT_EQ(reference.time(), restarted.time());
  for (std::size_t p = 0; p < reference.points().size(); ++p)
  {
    ASSERT_EQ(reference.points().id[p], restarted.points().id[p]);
    EXPECT_EQ(reference.points().position[p], restarted.points().position[p]);
    EXPECT_EQ(reference.points().velocity[p], restarted.points().velocity[p]);
    EXPECT_EQ(reference.points().failure[p], restarted.points().failure[p]);
    const materials::PlasticHistory* history = reference.points().plastic_of(p);
    ASSERT_EQ(history != nullptr, restarted.points().plastic_of(p) != nullptr);
    ASSERT_EQ(history != nullptr, plastic_ball && p >= reference.points().begin_of(1));
    if (history)
    {
      EXPECT_EQ(history->equivalent_plastic_strain,
                restarted.points().plastic_of(p)->equivalent_plastic_strain);
      most_plastic = std::max(most_plastic, history->equivalent_plastic_strain);
    }
  }
  if (plastic_ball)
  {
    EXPECT_GT(most_plastic, 1e-3) << "the ball should yield, or the test checks nothing";
  }
  EXPECT_EQ(reference.diagnostics().bodies[1].velocity, restarted.diagnostics().bodies[1].velocity);
  EXPECT_EQ(reference.contact_dissipation(), restarted.contact_dissipation());
  EXPECT_EQ(reference.support_dissipation(), restarted.support_dissipation());
}

INSTANTIATE_TEST_SUITE_P(Ball, MpmCheckpointBall, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "ElasticPlastic" : "Rigid"; });

TEST(MpmCheckpoint, TruncatedOrForeignCheckpointsAreRefused)
{
  const mpm::SceneParameters scene = impact_scene();
  mpm::Solver solver(scene);
  solver.advance();
  std::stringstream full;
  solver.save(full);
  const std::string bytes = full.str();

  std::stringstream truncated(bytes.substr(0, bytes.size() / 2));
  mpm::Solver other(scene);
  EXPECT_THROW(other.restore(truncated), std::runtime_error);

  std::stringstream garbage("not a checkpoint at all");
  EXPECT_THROW(other.restore(garbage), std::runtime_error);

  mpm::SceneParameters one_body = scene;
  one_body.bodies.pop_back();
  mpm::Solver foreign(one_body);
  std::stringstream copy(bytes);
  EXPECT_THROW(foreign.restore(copy), std::runtime_error);
}
