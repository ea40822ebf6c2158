// The domain faces' supports as an energy sink: the kinetic energy a fixed or roller face takes
// from the points is booked (Solver::support_dissipation), exactly in a step without forces,
// with contact at the same nodes, and so that a block stopped by a fixed face closes its
// energy balance as the step shrinks; the book survives a checkpoint.
#include "mpm/solver.h"
#include "scene_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace vulnus;
using mpm::Vector3;

namespace
{
using F = mpm::FaceCondition;

/// A 4 mm gel block touching the x- face (1 mm cells, 2 points per cell and direction).
mpm::SceneParameters block_on_x_minus(const F condition, const Vector3& velocity)
{
  mpm::SceneParameters scene = test::empty_scene(Vector3::Zero(), Vector3(12e-3, 12e-3, 12e-3), 1e-3);
  scene.domain_faces = {{condition, F::free, F::free, F::free, F::free, F::free}};
  scene.materials.push_back(test::elastic_material("gel", 1e5, 1e4));
  scene.bodies.push_back(test::box_body("block", "gel", Vector3(0, 4e-3, 4e-3), Vector3(4e-3, 8e-3, 8e-3), 1000.0, 2));
  scene.bodies[0].initial_velocity = velocity;
  return scene;
}
} // namespace

// In the first step no stress acts (F = I), so the points' kinetic energy changes by what the
// face takes alone. With linear shapes and FLIP a point at x < h keeps x / h of the velocity
// component the face stops: it loses m |v_n|^2 (1 - (x / h)^2) / 2.
TEST(SupportEnergy, AFaceBooksTheKineticEnergyItStopsInAStep)
{
  for (const F condition : {F::fixed, F::roller})
    for (const auto scheme : {mpm::UpdateScheme::usl, mpm::UpdateScheme::musl})
      for (const auto shape : {mpm::ShapeFunction::linear, mpm::ShapeFunction::gimp})
      {
        // Fixed: sliding along the face; roller: driven into it (and sliding).
        const Vector3 v0 = condition == F::fixed ? Vector3(0, 0, 0.2) : Vector3(-0.2, 0, 0.1);
        mpm::SceneParameters scene = block_on_x_minus(condition, v0);
        scene.update_scheme = scheme;
        scene.shape_function = shape;
        mpm::Solver solver(scene);
        const mpm::Particles& points = solver.points();
        const double h = scene.cell_size;
        const Vector3 stopped = condition == F::fixed ? v0 : Vector3(v0[0], 0, 0);
        double expected = 0.0;
        for (std::size_t p = 0; p < points.size(); ++p)
        {
          const double x = points.position[p][0] / h;
          if (x < 1.0)
            expected += 0.5 * points.mass[p] * stopped.squaredNorm() * (1.0 - x * x);
        }
        const double before = solver.diagnostics().kinetic_energy;
        solver.advance();
        const double lost = before - solver.diagnostics().kinetic_energy;
        EXPECT_GT(lost, 0.05 * before); // a quarter of the block is within a cell of the face
        EXPECT_NEAR(solver.support_dissipation(), lost, 1e-9 * before);
        if (shape == mpm::ShapeFunction::linear)
        {
          EXPECT_NEAR(lost, expected, 1e-9 * before);
        }
      }
}

// Two blocks on the fixed face closing on each other: where they meet on the face, contact
// and the supports correct the same nodes; the two books add up to the points' whole loss.
TEST(SupportEnergy, ContactAndSupportsShareTheCorrectionOfAFaceNode)
{
  mpm::SceneParameters scene = block_on_x_minus(F::fixed, Vector3(0, 0.2, 0));
  scene.bodies[0].box_max[1] = 6e-3;
  mpm::BodyParameters other = scene.bodies[0];
  other.name = "other";
  other.box_min[1] = 6e-3;
  other.box_max[1] = 8e-3;
  other.initial_velocity = Vector3(0, -0.2, 0.1);
  scene.bodies.push_back(other);
  scene.contact.friction_coefficient = 0.0;
  mpm::Solver solver(scene);
  const double before = solver.diagnostics().kinetic_energy;
  solver.advance();
  const double lost = before - solver.diagnostics().kinetic_energy;
  EXPECT_GT(solver.contact_dissipation(), 0.0);
  EXPECT_GT(solver.support_dissipation(), 0.0);
  EXPECT_NEAR(solver.contact_dissipation() + solver.support_dissipation(), lost, 1e-9 * before);
}

namespace
{
/// An 8 mm block driven at 0.5 m/s into the fixed x- face (a twentieth of the wave speed), run
/// for the wave's round trip through it. Returns the largest |balance error| of the run
/// (kinetic, strain and booked energies against the start's); sets the supports' share.
double block_into_fixed_face(const double cfl, double* supports_share)
{
  mpm::SceneParameters scene = block_on_x_minus(F::fixed, Vector3(-0.5, 0, 0));
  scene.bodies[0].box_max[0] = 8e-3;
  scene.cfl = cfl;
  mpm::Solver solver(scene);
  const double initial = solver.initial_energy();
  double worst = 0.0;
  while (solver.time() < 1.5e-3)
  {
    solver.advance();
    const mpm::SceneDiagnostics d = solver.diagnostics();
    const double accounted = d.kinetic_energy + d.strain_energy + d.dissipated_energy +
                             solver.contact_dissipation() + solver.support_dissipation();
    worst = std::max(worst, std::abs(accounted - initial) / initial);
  }
  *supports_share = solver.support_dissipation() / initial;
  std::cout << "CFL " << cfl << ": " << solver.step_count() << " steps, supports took "
            << *supports_share << " of the energy, largest balance error " << worst << "\n";
  return worst;
}
} // namespace

// Unbooked, the balance misses the supports' whole share (about a tenth of the energy here).
// Booked as the stopped components' whole change over the step (the forces' share at a
// stopped node included, since the strain energy sees that node at rest), the error left is
// the step's own and halves with it: measured 0.023 and 0.0125 of the energy at CFL 0.4 and
// 0.2, the supports taking 0.139 and 0.129 (their book converges with that error). Booked
// without the forces' share, the error was 0.053 and 0.033.
TEST(SupportEnergy, ABlockStoppedByAFixedFaceClosesItsBalanceAsTheStepIsHalved)
{
  double share = 0.0, share_half = 0.0;
  const double error = block_into_fixed_face(0.4, &share);
  const double error_half = block_into_fixed_face(0.2, &share_half);
  EXPECT_GT(share, 0.05); // the face takes a good part: unbooked, the balance would miss it
  EXPECT_LT(error, 0.25 * share);
  EXPECT_LT(error_half, 0.6 * error); // first order in the step
  EXPECT_NEAR(share_half, share, error);
}

TEST(SupportEnergy, TheSupportsBookSurvivesACheckpoint)
{
  const mpm::SceneParameters scene = block_on_x_minus(F::fixed, Vector3(-0.5, 0, 0.2));
  mpm::Solver reference(scene);
  for (int i = 0; i < 5; ++i)
    reference.advance();
  std::stringstream checkpoint;
  reference.save(checkpoint);
  for (int i = 0; i < 5; ++i)
    reference.advance();
  mpm::Solver restarted(scene);
  restarted.restore(checkpoint);
  for (int i = 0; i < 5; ++i)
    restarted.advance();
  EXPECT_GT(reference.support_dissipation(), 0.0);
  EXPECT_EQ(reference.support_dissipation(), restarted.support_dissipation());
}
