// A following interface (Hybrid/Interface = following): a block that drifts across grid cells
// exchanges momentum exactly through its moving interface, restarts bit for bit in a window's
// middle, and a uniform deformation of a drifting block stays uniform across it, where an
// interface held on its starting grid nodes drifts off.
#include "coupling/hybrid_solver.h"
#include "hybrid_test_scenes.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace vulnus::coupling
{
namespace
{
using testing::block_scene;
using testing::scheme_name;
using testing::positions_on_all_ranks;
using testing::uniform_far_field;
using testing::zone;

class FollowingInterface : public ::testing::TestWithParam<CouplingScheme>
{
};

/// The 12 mm block of the patch tests, h = 1 mm, its 4 mm zone in the middle, on a grid wide
/// enough for it to drift 3 mm along each axis.
HybridScene drifting_block(const CouplingScheme scheme, const InterfacePlacement placement)
{
  const double h = 1e-3;
  mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, h);
  s.domain_min = {-0.003, -0.003, -0.003};
  s.domain_max = {0.015, 0.015, 0.015};
  s.cfl = scheme == CouplingScheme::multi_step ? 0.1 : 0.4;
  HybridParameters hybrid = zone({0.004, 0.004, 0.004}, {0.008, 0.008, 0.008}, scheme);
  hybrid.interface = placement;
  HybridScene split = decompose(s, hybrid, uniform_far_field(h));
  for (auto& face : split.fe.faces)
    face.condition = fem::FaceParameters::Condition::free;
  return split;
}

/// Drift (0.5, 0.5/3, 0.5/3) m/s: 1.5, 0.5 and 0.5 cells over the 3 ms run.
const mpm::Vector3 drift(0.5, 0.5 / 3.0, 0.5 / 3.0);

// Free block drifting 1.5 cells obliquely with a bump of velocity on top: the interface leaves
// its grid nodes and takes new ones every step or window, and momentum still crosses exactly.
TEST_P(FollowingInterface, ADriftingBlockExchangesMomentumExactly)
{
  HybridSolver solver(drifting_block(GetParam(), InterfacePlacement::following), MPI_COMM_WORLD);
  auto field = [](const mpm::Vector3& x) -> mpm::Vector3 {
    const double bump = std::exp(-(x - mpm::Vector3(0.006, 0.006, 0.006)).squaredNorm() / 4e-6);
    return drift + mpm::Vector3(0.3 * bump, -0.2 * bump, 0.1 * bump * x[0] / 0.012);
  };
  solver.set_initial_velocity(field);
  const Eigen::Vector3d p0 = solver.total_momentum();
  const double e0 = solver.mpm().diagnostics().kinetic_energy + solver.fe_mechanical_energy();
  const double p_scale = 1000.0 * std::pow(0.012, 3) * 0.5;
  double worst = 0.0;
  std::size_t most_shared = 0;
  while (solver.time() < 3e-3)
  {
    solver.advance();
    most_shared = std::max(most_shared, solver.n_shared_grid_nodes());
    if (solver.at_window_end())
      worst = std::max(worst, (solver.total_momentum() - p0).norm());
  }
  const auto d = solver.mpm().diagnostics();
  const double e1 = d.kinetic_energy + d.strain_energy + d.dissipated_energy +
                    solver.fe_mechanical_energy();
  std::cout << "momentum drift / (m v): " << worst / p_scale << ", energy change / E0: "
            << (e1 - e0) / e0 << ", interface nodes " << solver.n_interface_nodes()
            << ", most grid nodes shared " << most_shared << '\n';
  // The interface has left its grid nodes: its nodes are spread over several each.
  EXPECT_GT(most_shared, 2 * solver.n_interface_nodes());
  EXPECT_LT(worst, 1e-12 * p_scale);
  EXPECT_LT((solver.ledger().mpm_impulse + solver.ledger().fe_impulse +
             solver.impulse_in_transit()).norm(),
            1e-12 * p_scale);
  EXPECT_LT(std::abs(e1 - e0), 0.02 * e0);
}

// A multi-step run saved in the middle of a window after the interface has left its grid
// nodes (its placement, spread and velocity gradients are part of the checkpoint) continues
// bit for bit in a solver built afresh.
TEST(FollowingInterfaceRestart, AWindowSavedMidWayContinuesBitForBit)
{
  auto build = []() {
    auto solver = std::make_unique<HybridSolver>(
      drifting_block(CouplingScheme::multi_step, InterfacePlacement::following), MPI_COMM_WORLD);
    solver->set_initial_velocity([](const mpm::Vector3& x) -> mpm::Vector3 {
      const double bump = std::exp(-(x - mpm::Vector3(0.006, 0.006, 0.006)).squaredNorm() / 4e-6);
      return drift + mpm::Vector3(0.3 * bump, -0.2 * bump, 0.0);
    });
    return solver;
  };
  std::unique_ptr<HybridSolver> uninterrupted = build();
  // 1.3 ms: the interface has drifted 0.65 cell along x.
  while (uninterrupted->time() < 1.3e-3 || uninterrupted->at_window_end())
    uninterrupted->advance();
  ASSERT_GT(uninterrupted->n_shared_grid_nodes(), 2 * uninterrupted->n_interface_nodes());
  std::stringstream checkpoint;
  uninterrupted->save(checkpoint);
  std::unique_ptr<HybridSolver> restarted = build();
  restarted->restore(checkpoint);
  for (int step = 0; step < 20; ++step)
  {
    uninterrupted->advance();
    restarted->advance();
  }
  std::stringstream a, b;
  uninterrupted->save(a);
  restarted->save(b);
  EXPECT_TRUE(a.str() == b.str()) << "the two runs' states differ";
  EXPECT_EQ(uninterrupted->total_momentum(), restarted->total_momentum());
  EXPECT_GT(uninterrupted->ledger().fe_steps, 40u); // 51 windows by then
}

/// Largest departure of a point's velocity from drift + L X, and of a point's stress from the
/// far field's mean stress, at end_time (3 ms: the block has drifted 1.5 cells), with v =
/// drift + L X prescribed on its outer faces.
struct DriftErrors
{
  double velocity = 0.0;
  double stress = 0.0;
  double stress_scale = 0.0;
};

DriftErrors drifting_patch(const CouplingScheme scheme, const InterfacePlacement placement,
                           const double end_time)
{
  Eigen::Matrix3d L;
  L << 0.4, 0.1, 0.0, //
    0.05, -0.2, 0.1,  //
    0.0, 0.15, 0.3;   // 1/s: 0.1 % strain over the run
  auto field = [&L](const mpm::Vector3& x) -> mpm::Vector3 { return drift + L * x; };
  HybridScene split = drifting_block(scheme, placement);
  HybridSolver solver(split, MPI_COMM_WORLD, [&](fem::FarFieldSolver& fe) {
    for (unsigned int f = 0; f < fem::n_slab_faces; ++f)
      fe.set_face_velocity_field(f, [&](const dealii::Point<3>& X, double) {
        const mpm::Vector3 v = field(mpm::Vector3(X[0], X[1], X[2]));
        return dealii::Tensor<1, 3>({v[0], v[1], v[2]});
      });
  });
  solver.set_initial_velocity(field);
  const std::map<std::uint32_t, mpm::Vector3> start = positions_on_all_ranks(solver);
  while (solver.time() < end_time)
    solver.advance();
  DriftErrors e;
  const mpm::Particles& p = solver.mpm().points();
  for (std::size_t i = 0; i < p.size(); ++i)
    e.velocity = std::max(e.velocity, (p.velocity[i] - field(start.at(p.id[i]))).norm());
  const dealii::Tensor<2, 3> fe_stress = solver.fe().average_cauchy_stress();
  for (unsigned int a = 0; a < 3; ++a)
    for (unsigned int b = 0; b < 3; ++b)
    {
      e.stress_scale = std::max(e.stress_scale, std::abs(fe_stress[a][b]));
      for (std::size_t i = 0; i < p.size(); ++i)
        e.stress = std::max(e.stress, std::abs(mpm::full_tensor(p.stress[i])(a, b) - fe_stress[a][b]));
    }
  e.velocity = dealii::Utilities::MPI::max(e.velocity, solver.fe().communicator());
  e.stress = dealii::Utilities::MPI::max(e.stress, solver.fe().communicator());
  e.stress_scale = dealii::Utilities::MPI::max(e.stress_scale, solver.fe().communicator());
  return e;
}

// A uniform deformation of a block drifting across the cells. On its starting grid nodes the
// interface imposes each FE node's velocity where the node no longer is (off by L u), so the
// zone's strain departs from the far field's more the further the block drifts. A following
// interface meets the grid where its nodes are: its error is that of a surface between grid
// nodes (a grid node a fraction of a cell off the interface sticks to the interface's velocity
// by its mass share there, first order in the cell), which grows far less with the drift.
TEST_P(FollowingInterface, AUniformDeformationOfADriftingBlockStaysUniform)
{
  const DriftErrors held_half = drifting_patch(GetParam(), InterfacePlacement::grid_nodes, 1e-3);
  const DriftErrors held = drifting_patch(GetParam(), InterfacePlacement::grid_nodes, 3e-3);
  const DriftErrors following_half = drifting_patch(GetParam(), InterfacePlacement::following, 1e-3);
  const DriftErrors following = drifting_patch(GetParam(), InterfacePlacement::following, 3e-3);
  auto relative = [](const DriftErrors& e) { return e.stress / e.stress_scale; };
  std::cout << "stress error / stress after 0.5 and 1.5 cells of drift: on grid nodes "
            << relative(held_half) << ", " << relative(held) << "; following "
            << relative(following_half) << ", " << relative(following)
            << "; velocity error after 1.5 cells (m/s): on grid nodes " << held.velocity
            << ", following " << following.velocity << '\n';
  ASSERT_GT(following.stress_scale, 10.0); // Pa: the block is really deformed
  // Measured (same step and multi step): on grid nodes 1.1 and 6.0 (5.4 times), following 0.35
  // and 0.63 (1.8 times: the error still accumulates while the interface is off the nodes);
  // velocity 0.042 against 0.0055-0.0063 m/s.
  EXPECT_GT(relative(held), 3.0 * relative(held_half));
  EXPECT_LT(relative(following), 2.5 * relative(following_half));
  EXPECT_LT(relative(following), 0.2 * relative(held));
  EXPECT_LT(following.velocity, 0.25 * held.velocity);
}

INSTANTIATE_TEST_SUITE_P(Schemes, FollowingInterface,
                         ::testing::Values(CouplingScheme::same_step, CouplingScheme::multi_step),
                         scheme_name);
} // namespace
} // namespace vulnus::coupling
