// Multi-velocity-field contact: momentum conservation and no interpenetration in a
// collision, Coulomb friction on an incline (analytic acceleration), rigid projectile, and
// the proximity check (contact starts when the surfaces touch, not a cell before), and
// Uintah's compression criterion at one node.
#include "mpm/grid_update.h"
#include "mpm/solver.h"
#include "scene_fixtures.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace vulnus;
using mpm::Vector3;

TEST(MpmContact, CollisionConservesMomentumWithoutInterpenetration)
{
  for (const double friction : {0.0, 0.08, -1.0})
  {
    // Relative speed 1.5 m/s, about 1/7 of the wave speed: small deformation, so the contact
    // surface stays near a plane normal to x.
    mpm::SceneParameters scene =
        test::two_gel_spheres(1000.0, 2000.0, Vector3(1.0, 0.2, 0), Vector3(-0.5, 0, 0.0));
    scene.contact.friction_coefficient = friction;
    mpm::Solver solver(scene);
    const mpm::SceneDiagnostics start = solver.diagnostics();
    const double scale = start.bodies[0].mass * 1.0;
    double closest_gap = 1.0;
    bool touched = false;
    while (solver.time() < 6e-3)
    {
      solver.advance();
      const mpm::SceneDiagnostics d = mpm::compute_diagnostics(solver.points(), Vector3::UnitX(), Vector3::Zero());
      EXPECT_LT((d.momentum - start.momentum).norm(), 1e-12 * scale) << "friction " << friction;
      // The spheres stay on their own sides of the plane between them (head-on along x).
      const double gap = d.bodies[1].min_along - d.bodies[0].max_along;
      closest_gap = std::min(closest_gap, gap);
      touched = touched || solver.contact_nodes() > 0;
    }
    EXPECT_TRUE(touched);
    if (friction >= 0.0) // no-slip glues them: the gap test applies to contact that separates
    {
      // Multi-velocity contact acts once the bodies share nodes, so points may close in to
      // less than a cell but must not pass: bound a quarter cell.
      EXPECT_GT(closest_gap, -0.25e-3) << "friction " << friction;
      // The bodies bounced: the light one now moves left.
      EXPECT_LT(solver.diagnostics().bodies[0].velocity[0], 0.0);
    }
  }
}

namespace
{
/// A stiff block resting on a rigid plate, gravity tilted by `angle` so the block slides
/// along x. Returns the block's mean acceleration along x from a least-squares parabola fit.
double sliding_acceleration(const double friction, const double angle)
{
  const double g = 9.81;
  mpm::SceneParameters scene = test::empty_scene(Vector3(0, 0, 0), Vector3(40e-3, 10e-3, 4e-3), 1e-3);
  using F = mpm::FaceCondition;
  scene.domain_faces = {{F::free, F::free, F::free, F::free, F::roller, F::roller}};
  scene.contact.friction_coefficient = friction;
  scene.gravity = Vector3(g * std::sin(angle), -g * std::cos(angle), 0.0);
  scene.cfl = 0.3;
  scene.materials.push_back(test::elastic_material("block", 2e6, 2e5));
  scene.materials.push_back(test::rigid_material("plate"));
  scene.bodies.push_back(test::box_body("block", "block", Vector3(2e-3, 3e-3, 0), Vector3(12e-3, 7e-3, 4e-3), 1000.0, 2));
  scene.bodies.push_back(test::box_body("plate", "plate", Vector3(0, 0, 0), Vector3(40e-3, 3e-3, 4e-3), 1000.0, 2));
  scene.bodies[1].rigid_motion = mpm::RigidMotion::prescribed;
  mpm::Solver solver(scene);
  // Let the block settle on the plate for 5 ms, then fit x(t) = a/2 t^2 + b t + c.
  const double settle = 5e-3, end = 25e-3;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  while (solver.time() < end)
  {
    solver.advance();
    if (solver.time() < settle)
      continue;
    const double t = solver.time() - settle;
    const Eigen::Vector3d basis(0.5 * t * t, t, 1.0);
    normal += basis * basis.transpose();
    rhs += basis * solver.diagnostics().bodies[0].centroid[0];
  }
  return normal.ldlt().solve(rhs)[0];
}
} // namespace

TEST(MpmContact, FrictionlessBlockSlidesWithGSinTheta)
{
  const double angle = M_PI / 6;
  const double expected = 9.81 * std::sin(angle);
  EXPECT_NEAR(sliding_acceleration(0.0, angle), expected, 0.03 * expected);
}

TEST(MpmContact, CoulombFrictionSlowsTheSlide)
{
  const double angle = M_PI / 6, mu = 0.08;
  const double expected = 9.81 * (std::sin(angle) - mu * std::cos(angle));
  EXPECT_NEAR(sliding_acceleration(mu, angle), expected, 0.03 * expected);
}

TEST(MpmContact, FreeRigidProjectileIsSlowedByTheTarget)
{
  mpm::Solver solver(test::rigid_ball_into_gel_slab());
  const mpm::SceneDiagnostics start = solver.diagnostics();
  while (!solver.finished())
    solver.advance();
  const mpm::SceneDiagnostics end = solver.diagnostics();
  const double v_end = end.bodies[1].velocity[1];
  EXPECT_LT(v_end, 50.0 - 1e-3);
  EXPECT_GT(v_end, 0.0);
  // Momentum given to the slab equals momentum lost by the ball (rigid reaction), up to
  // what the fixed faces absorb (none here: all faces free).
  const double lost = start.bodies[1].mass * (50.0 - v_end);
  EXPECT_NEAR(end.bodies[0].velocity[1] * end.bodies[0].mass, lost, 1e-6 * lost + 1e-12);
}

// The progress line's time left: at the start the ball's tail must cover the distance to the
// slab's far face (y = 4 mm) at 50 m/s; the estimate never passes the end time.
TEST(MpmContact, ExpectedEndIsWhenTheProjectileTailPassesTheTarget)
{
  mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
  scene.stop_when_projectile_exits = true;
  scene.end_time = 1.0;
  const mpm::Solver solver(scene);
  const mpm::Particles& points = solver.points();
  double tail = 1.0;
  for (std::size_t p = points.begin_of(1); p < points.end_of(1); ++p)
    tail = std::min(tail, points.position[p][1]);
  const double far_face = scene.bodies[0].box_max[1];
  EXPECT_NEAR(solver.expected_end_time(), (far_face - tail) / 50.0, 1e-12);
  scene.end_time = 1e-5; // before the exit: the end time bounds it
  EXPECT_DOUBLE_EQ(mpm::Solver(scene).expected_end_time(), 1e-5);
}

namespace
{
/// A rigid plate moving at 1 m/s towards a resting gel block across a 2 mm gap (2 cells,
/// 2 points per cell), overhanging the block by 2 mm so that its normal is the same at every
/// node the block reaches: the time the block first feels a contact force.
double first_contact_time(const double proximity_distance, const bool exact_surface = false)
{
  mpm::SceneParameters scene = test::empty_scene(Vector3(-4e-3, -2e-3, -4e-3), Vector3(14e-3, 12e-3, 8e-3), 1e-3);
  scene.contact.friction_coefficient = 0.0;
  scene.contact.proximity_distance = proximity_distance;
  scene.contact.exact_rigid_surface = exact_surface;
  scene.end_time = 2.6e-3;
  scene.materials.push_back(test::elastic_material("gel", 2e6, 2e5));
  scene.materials.push_back(test::rigid_material("steel"));
  scene.bodies.push_back(test::box_body("block", "gel", Vector3(0, 0, 0), Vector3(10e-3, 4e-3, 4e-3), 1000.0, 2));
  scene.bodies.push_back(test::box_body("plate", "steel", Vector3(-2e-3, 6e-3, -2e-3), Vector3(12e-3, 8e-3, 6e-3), 8000.0, 2));
  scene.bodies[1].rigid_motion = mpm::RigidMotion::prescribed;
  scene.bodies[1].initial_velocity = Vector3(0, -1.0, 0);
  mpm::Solver solver(scene);
  while (!solver.finished())
  {
    const double t = solver.time();
    solver.advance();
    if (solver.contact_forces()[0].norm() > 0.0)
      return t; // the force acted over the step from t
  }
  return scene.end_time;
}
} // namespace

// The surfaces touch at t = gap / v = 2 ms. Touching bodies' mass centres seen from a node
// sit 2/3 to 1 cell apart (linear weights, 2 points per cell); with the default distance of
// 0.8 cells (about their mean), faded in over +-0.05 cells, the first partial correction comes
// at most 0.18 cells before the touch (measured 0.17: 1.83 ms) and no node waits for more than
// 0.25 cells of overlap. Without the check contact acts wherever both bodies reach a node:
// 0.75 cells early here (the plate's lowest points reach the node above the block's top
// points at 1.25 ms).
TEST(MpmContact, ProximityCheckStartsContactWhenTheSurfacesTouch)
{
  const double touch = 2e-3;
  const double with_check = first_contact_time(mpm::ContactParameters().proximity_distance);
  EXPECT_NEAR(with_check, touch, 0.2e-3);
  RecordProperty("first_contact_with_check_s", std::to_string(with_check));
  const double without_check = first_contact_time(0.0);
  EXPECT_LT(without_check, touch - 0.5e-3);
}

// With the plate's exact surface the gap runs from the plate's face to the block's mass
// centre at a node less half the block's point spacing. At the block's top nodes that mass
// centre lies 1/8 cell below the top points (linear weights, 2 points per cell), so the first
// correction comes 1/8 cell after the touch, less the fade-in band (0.05 cells) and one
// step's approach: 2.075 ms here, and in any case within 0.15 cells of the touch.
TEST(MpmContact, ExactRigidSurfaceStartsContactWhenTheSurfacesTouch)
{
  const double touch = 2e-3;
  const double exact = first_contact_time(mpm::ContactParameters().proximity_distance, true);
  EXPECT_NEAR(exact, touch, 0.15e-3);
  // The proximity distance does not apply to a rigid body's exact surface.
  EXPECT_EQ(first_contact_time(0.0, true), exact);
}

// The rigid ball's exact surface: it weighs its sphere's mass, the slab's momentum gain is
// the ball's loss, the ball is slowed, and it is slowed less than with the mass-centre gap,
// which meets the slab up to a fraction of a cell beyond the ball's surface (measured: 45.77
// against 44.03 m/s left of 50).
TEST(MpmContact, ExactRigidSurfaceConservesMomentumAndBitesLess)
{
  double end_velocity[2] = {0.0, 0.0};
  for (const bool exact : {false, true})
  {
    mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
    scene.contact.exact_rigid_surface = exact;
    mpm::Solver solver(scene);
    const mpm::SceneDiagnostics start = solver.diagnostics();
    const double shape_mass = 8930.0 * 4.0 / 3.0 * M_PI * std::pow(2.5e-3, 3);
    if (exact) // the ball weighs its sphere's mass, not its points' sampled volume's
      EXPECT_NEAR(start.bodies[1].mass, shape_mass, 1e-12 * shape_mass);
    else
      EXPECT_GT(std::abs(start.bodies[1].mass - shape_mass), 1e-3 * shape_mass);
    while (!solver.finished())
      solver.advance();
    const mpm::SceneDiagnostics end = solver.diagnostics();
    const double v_end = end.bodies[1].velocity[1];
    EXPECT_LT(v_end, 50.0 - 1e-3);
    const double lost = start.bodies[1].mass * (50.0 - v_end);
    EXPECT_NEAR(end.bodies[0].velocity[1] * end.bodies[0].mass, lost, 1e-6 * lost + 1e-12);
    end_velocity[exact] = v_end;
  }
  EXPECT_GT(end_velocity[1], end_velocity[0]);
  RecordProperty("end_velocity_points", std::to_string(end_velocity[0]));
  RecordProperty("end_velocity_exact", std::to_string(end_velocity[1]));
}

// Two rigid bodies cannot give way to each other: their meeting stops the run naming both,
// instead of letting them pass through (a rigid bullet would end inside a rigid wall).
TEST(MpmContact, TwoRigidBodiesMeetingStopTheRun)
{
  mpm::SceneParameters scene = test::rigid_ball_into_gel_slab();
  scene.materials.push_back(test::rigid_material("wall"));
  scene.bodies[0].material = "wall";
  scene.bodies[0].rigid_motion = mpm::RigidMotion::prescribed;
  mpm::Solver solver(scene);
  const std::string message = test::run_until_blow_up(solver);
  EXPECT_NE(message.find("rigid bodies 'slab' and 'ball' met"), std::string::npos) << message;
  // The ball (50 m/s, 0.5 mm from the wall) meets it within about 1.5 cells of travel.
  EXPECT_LT(solver.time(), 2e-3 / 50.0);
}

namespace
{
/// Two deformable bodies of 1 g at one interior node of a 1 mm grid, body 0 below body 1
/// (outward normal +y), with friction 0.08 and nothing set on the nodal velocities.
struct OneContactNode
{
  mpm::Grid grid{Vector3::Zero(), Vector3::Constant(4e-3), 1e-3};
  mpm::GridFields fields;
  mpm::GridUpdateSettings settings;

  OneContactNode()
  {
    grid.clear_active_nodes();
    grid.mark(grid.node_key(2, 2, 2), 0);
    grid.number_active_nodes(1);
    fields.n_bodies = 2;
    fields.resize(1);
    fields.stress_sum.assign(2, mpm::SymmetricTensor::Zero());
    for (int b = 0; b < 2; ++b)
    {
      fields.data[b] = mpm::NodeBodyData();
      fields.data[b].mass = 1e-3;
      fields.data[b].mass_gradient = Vector3(0.0, b == 0 ? 1.0 : -1.0, 0.0);
    }
    settings.time_step = 1e-7;
    settings.contact = true;
    settings.friction_coefficient = 0.08;
    settings.body_is_rigid = {0, 0};
    settings.rigid_velocity = {Vector3::Zero(), Vector3::Zero()};
  }
};

/// The two bodies separating along y at 1 m/s each, with the given nodal stress sum sigma_yy
/// (n . S n for the normal along y); their velocities after resolve_contacts.
std::array<Vector3, 2> separating_pair(const bool hold_compressed, const double normal_stress)
{
  OneContactNode node;
  for (int b = 0; b < 2; ++b)
  {
    node.fields.stress_sum[b][1] = normal_stress;
    node.fields.velocity_new[b] = Vector3(0.0, b == 0 ? -1.0 : 1.0, 0.0);
  }
  node.settings.hold_compressed_surfaces = hold_compressed;
  mpm::GridUpdateResult result;
  mpm::resolve_contacts(node.grid, node.settings, node.fields, result);
  return {node.fields.velocity_new[0], node.fields.velocity_new[1]};
}
} // namespace

TEST(MpmContact, CompressionCriterionHoldsOnlyCompressedSurfacesTogether)
{
  // Approach criterion: separating bodies move independently, compressed or not.
  for (const double stress : {-1e3, 1e3})
  {
    const auto v = separating_pair(false, stress);
    EXPECT_EQ(v[0], Vector3(0.0, -1.0, 0.0));
    EXPECT_EQ(v[1], Vector3(0.0, 1.0, 0.0));
  }
  // Uintah's criterion: a compressed surface holds them (the separation is removed, the
  // momentum kept); one in tension lets them go.
  const auto held = separating_pair(true, -1e3);
  EXPECT_NEAR((held[1] - held[0]).norm(), 0.0, 1e-12);
  EXPECT_NEAR((held[0] + held[1]).norm(), 0.0, 1e-12);
  const auto free = separating_pair(true, 1e3);
  EXPECT_EQ(free[0], Vector3(0.0, -1.0, 0.0));
  EXPECT_EQ(free[1], Vector3(0.0, 1.0, 0.0));
}

TEST(MpmContact, SecondPassCorrectsTheProjectedVelocitiesBeforeTheForces)
{
  // Two bodies approaching at one node (body 0 below, outward normal +y), no forces: with
  // Uintah's two passes the projected velocities v^n are corrected already (so FLIP's
  // increments v_new - v^n leave the correction out); with one pass v^n is as projected.
  for (const bool two_passes : {false, true})
  {
    OneContactNode node;
    mpm::GridFields& fields = node.fields;
    for (int b = 0; b < 2; ++b)
      fields.data[b].momentum = 1e-3 * Vector3(0.0, b == 0 ? 1.0 : -1.0, 0.0);
    node.settings.correct_projected_velocities = two_passes;
    mpm::GridUpdateResult result;
    mpm::update_grid(node.grid, node.settings, fields, result);
    if (two_passes)
    {
      EXPECT_NEAR(fields.velocity[0].norm(), 0.0, 1e-12);
      EXPECT_NEAR(fields.velocity[1].norm(), 0.0, 1e-12);
    }
    else
    {
      EXPECT_EQ(fields.velocity[0], Vector3(0.0, 1.0, 0.0));
      EXPECT_EQ(fields.velocity[1], Vector3(0.0, -1.0, 0.0));
    }
    // Either way the second pass leaves no approach after the step.
    mpm::resolve_contacts(node.grid, node.settings, fields, result);
    EXPECT_NEAR((fields.velocity_new[0] - fields.velocity_new[1]).y(), 0.0, 1e-12);
  }
}
