// A hybrid run distributed over the ranks of mpirun (MPM zone in slabs, FE far field in
// deal.II's partition) against the same scene run by one process on MPI_COMM_SELF: the points,
// the far field's energies and momentum and the interface ledger agree to round-off, also where
// an interface node's FE owner and the MPM slab holding its grid node are different ranks.
// Run under mpirun on 2 and 3 ranks only (CTest coupling_distributed_tests.np2/.np3).
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
struct DistributedCase
{
  CouplingScheme scheme;
  fem::TimeIntegrator integrator;
  /// Bound on point position differences, m, and the relative bound on FE energies and the
  /// interface works. Explicit: only the order of additions changes (node sums across slab
  /// cuts, interface sums over ranks): measured 1e-18 m (an ulp of the positions) and 1e-14
  /// relative; bounds 1e-12 m (1e-8 of the punch's 0.3 mm) and 1e-10. Implicit: the
  /// distributed AMG preconditioner changes the Krylov iterates, so each Newton solution may
  /// differ within the linear tolerance (1e-10 relative): measured 3e-13 relative; bounds
  /// 1e-10 m and 1e-8.
  double position_bound;
  double energy_bound;
  const char* name;
};

class HybridDistributed : public ::testing::TestWithParam<DistributedCase>
{
};

int world_size()
{
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

std::map<std::uint32_t, mpm::Vector3> positions_by_id(const mpm::Particles& p)
{
  std::map<std::uint32_t, mpm::Vector3> result;
  for (std::size_t i = 0; i < p.size(); ++i)
    result[p.id[i]] = p.position[i];
  return result;
}

TEST_P(HybridDistributed, ReproducesTheOneProcessRun)
{
  ASSERT_GE(world_size(), 2) << "run under mpirun with 2 or more ranks";
  const DistributedCase c = GetParam();
  mpm::SceneParameters scene = testing::indentation_scene();
  scene.end_time = 3e-4; // the punch 0.3 mm in
  fem::FeSceneParameters far_field = testing::uniform_far_field(1e-3);
  far_field.far_cell_size = 2e-3;
  far_field.grading_ratio = 1.5;
  far_field.integrator = c.integrator;
  far_field.time_step = 1e-5;
  const HybridScene split =
    decompose(scene, testing::zone({-0.006, 0.0, -0.006}, {0.006, 0.01, 0.006}, c.scheme), far_field);

  HybridSolver distributed(split, MPI_COMM_WORLD);
  HybridSolver alone(split, MPI_COMM_SELF);
  ASSERT_EQ(distributed.n_interface_nodes(), alone.n_interface_nodes());
  // The case the coupling must handle: FE owner and MPM slab of one node on different ranks.
  EXPECT_GT(distributed.n_interface_nodes_across_ranks(), 0u);
  EXPECT_EQ(alone.n_interface_nodes_across_ranks(), 0u);

  while (!distributed.finished())
    distributed.advance();
  while (!alone.finished())
    alone.advance();
  EXPECT_EQ(distributed.ledger().mpm_steps, alone.ledger().mpm_steps);
  EXPECT_EQ(distributed.ledger().fe_steps, alone.ledger().fe_steps);

  const fem::FeDiagnostics fd = distributed.fe().diagnostics(), fa = alone.fe().diagnostics();
  ASSERT_GT(fa.strain_energy, 0.0);
  EXPECT_NEAR(fd.strain_energy, fa.strain_energy, c.energy_bound * fa.strain_energy);
  EXPECT_NEAR(fd.kinetic_energy, fa.kinetic_energy,
              c.energy_bound * (fa.kinetic_energy + fa.strain_energy));
  const double work_scale = std::abs(alone.ledger().fe_work) + std::abs(alone.ledger().mpm_work);
  ASSERT_GT(work_scale, 0.0);
  EXPECT_NEAR(distributed.ledger().fe_work, alone.ledger().fe_work, c.energy_bound * work_scale);
  EXPECT_NEAR(distributed.ledger().mpm_work, alone.ledger().mpm_work, c.energy_bound * work_scale);
  const Eigen::Vector3d pd = distributed.total_momentum(), pa = alone.total_momentum();
  EXPECT_LE((pd - pa).norm(), c.energy_bound * std::max(pa.norm(), 1e-12)) << pd << "\n" << pa;

  const mpm::Particles gathered = distributed.mpm().gather_points();
  if (distributed.mpm().rank_group().rank() != 0)
    return;
  const auto expected = positions_by_id(alone.mpm().points());
  const auto result = positions_by_id(gathered);
  ASSERT_EQ(result.size(), expected.size());
  double worst = 0.0;
  for (const auto& [id, x] : expected)
  {
    const auto it = result.find(id);
    ASSERT_NE(it, result.end()) << "point " << id << " lost";
    worst = std::max(worst, (it->second - x).norm());
  }
  std::cout << c.name << " on " << world_size() << " ranks: largest point position difference "
            << worst << " m, " << distributed.n_interface_nodes_across_ranks() << " of "
            << distributed.n_interface_nodes() << " interface nodes across ranks, FE strain energy "
            << "relative difference " << (fd.strain_energy - fa.strain_energy) / fa.strain_energy
            << ", FE interface work " << (distributed.ledger().fe_work - alone.ledger().fe_work) / work_scale
            << "\n";
  EXPECT_LE(worst, c.position_bound);
}

INSTANTIATE_TEST_SUITE_P(
  Schemes, HybridDistributed,
  ::testing::Values(
    DistributedCase{CouplingScheme::same_step, fem::TimeIntegrator::central_difference, 1e-12,
                    1e-10, "same_step"},
    DistributedCase{CouplingScheme::multi_step, fem::TimeIntegrator::central_difference, 1e-12,
                    1e-10, "multi_step"},
    DistributedCase{CouplingScheme::multi_step, fem::TimeIntegrator::generalized_alpha, 1e-10,
                    1e-8, "multi_step_implicit"}),
  [](const ::testing::TestParamInfo<DistributedCase>& info) { return std::string(info.param.name); });
} // namespace
} // namespace vulnus::coupling
