// The same scene (slab with a velocity-driven hole, fixed sides) on all ranks of
// MPI_COMM_WORLD and on MPI_COMM_SELF of every rank: the results must agree to solver
// tolerance (run under `mpirun -np 2`; with one rank it compares two serial runs). Also a
// traction-loaded slab stepped to its end time with HDF5/XDMF output.
#include "fem/far_field_data.h"
#include "fem/far_field_solver.h"
#include "fem_test_scenes.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace
{
using namespace dealii;
using vulnus::fem::testing::integrator_name;
using namespace vulnus;
using namespace vulnus::fem;

FeSceneParameters holed_slab(const TimeIntegrator integrator)
{
  FeSceneParameters p;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{0.02, 0.006, 0.02}};
  p.has_hole = true;
  p.hole_min = {{0.008, 0.0, 0.008}};
  p.hole_max = {{0.012, 0.006, 0.012}};
  p.interface_cell_size = 0.002;
  p.far_cell_size = 0.004;
  p.grading_ratio = 1.5;
  p.integrator = integrator;
  p.time_step = 2e-4;
  p.newton_relative_tolerance = 1e-10;
  p.linear_relative_tolerance = 1e-12;
  p.interface_condition = InterfaceCondition::velocity_driven;
  p.fibers.kind = materials::FiberFieldParameters::Kind::rotating;
  p.fibers.end_coordinate = 0.006;
  return p;
}

struct Snapshot
{
  FeDiagnostics diagnostics;
  std::map<std::array<long, 3>, Tensor<1, 3>> displacement; ///< by node position in um
  FeMeshForOutput mesh;                                     ///< complete on rank 0
};

Snapshot run(const FeSceneParameters& p, const MPI_Comm comm, const unsigned int n_steps)
{
  FarFieldSolver solver(p, comm);
  solver.setup();
  std::vector<Tensor<1, 3>> v;
  for (const NodeRecord& node : solver.interface_nodes())
  {
    Tensor<1, 3> w;
    w[0] = 0.5; // m/s: the hole surface pushed along x
    w[1] = 0.1 * std::sin(100.0 * node.position[2]);
    v.push_back(w);
  }
  solver.set_interface_velocities(v);
  const double dt = solver.next_time_step();
  for (unsigned int s = 0; s < n_steps; ++s)
    solver.advance(dt);
  Snapshot snapshot;
  snapshot.diagnostics = solver.diagnostics();
  for (const NodeRecord& node : solver.locally_owned_nodes())
  {
    std::array<long, 3> key;
    for (unsigned int d = 0; d < 3; ++d)
      key[d] = std::lround(node.position[d] * 1e6);
    snapshot.displacement[key] = solver.displacement(node);
  }
  snapshot.mesh = solver.mesh_for_output();
  return snapshot;
}

/// Runs `p` on all ranks and on each rank alone: diagnostics and every owned node's
/// displacement agree to `tolerance`.
void expect_same_on_all_ranks(const FeSceneParameters& p, const unsigned int n_steps,
                              const double tolerance)
{
  const Snapshot world = run(p, MPI_COMM_WORLD, n_steps);
  const Snapshot self = run(p, MPI_COMM_SELF, n_steps);
  const FeDiagnostics& a = world.diagnostics;
  const FeDiagnostics& b = self.diagnostics;
  EXPECT_GT(a.kinetic_energy, 0.0);
  EXPECT_NEAR(a.kinetic_energy, b.kinetic_energy, tolerance * b.kinetic_energy);
  EXPECT_NEAR(a.strain_energy, b.strain_energy, tolerance * b.strain_energy);
  EXPECT_NEAR(a.external_work, b.external_work, tolerance * std::abs(b.external_work));
  for (unsigned int f = 0; f <= n_slab_faces; ++f)
    EXPECT_LT((a.face_reactions[f] - b.face_reactions[f]).norm(),
              tolerance * b.face_reactions[6].norm() + 1e-30)
        << "face " << f;
  // Every node this rank owns in the parallel run exists in its serial run.
  double max_difference = 0.0, max_u = 0.0;
  for (const auto& [key, u] : world.displacement)
  {
    const auto it = self.displacement.find(key);
    ASSERT_NE(it, self.displacement.end());
    max_difference = std::max(max_difference, (u - it->second).norm());
    max_u = std::max(max_u, it->second.norm());
  }
  max_difference = Utilities::MPI::max(max_difference, MPI_COMM_WORLD);
  max_u = Utilities::MPI::max(max_u, MPI_COMM_WORLD);
  EXPECT_LT(max_difference, tolerance * max_u);
}

class SameOnOneAndTwoRanks : public ::testing::TestWithParam<TimeIntegrator>
{
};

TEST_P(SameOnOneAndTwoRanks, DiagnosticsAndNodalDisplacementsAgree)
{
  const bool explicit_steps = GetParam() == TimeIntegrator::central_difference;
  expect_same_on_all_ranks(holed_slab(GetParam()), explicit_steps ? 40 : 4,
                           explicit_steps ? 1e-11 : 1e-7);
}

// One point per cell with hourglass control: its forces come from the same cells on every
// partition.
TEST(SameOnOneAndTwoRanksOnePoint, DiagnosticsAndNodalDisplacementsAgree)
{
  FeSceneParameters p = holed_slab(TimeIntegrator::central_difference);
  p.one_point_integration = true;
  expect_same_on_all_ranks(p, 40, 1e-11);
}

INSTANTIATE_TEST_SUITE_P(Integrators, SameOnOneAndTwoRanks,
                         ::testing::Values(TimeIntegrator::central_difference,
                                           TimeIntegrator::newmark),
                         integrator_name);

TEST(FeScene, TractionWorkBecomesKineticAndStrainEnergy)
{
  FeSceneParameters p = holed_slab(TimeIntegrator::central_difference);
  p.interface_condition = InterfaceCondition::free;
  p.faces[2].condition = FaceParameters::Condition::traction;
  p.faces[2].value = {{0.0, 500.0, 0.0}}; // Pa, pushing into the slab
  p.faces[2].profile = {TimeProfile::Kind::ramp, 1e-3};
  p.end_time = 1e-3;
  FarFieldSolver solver(p, MPI_COMM_WORLD);
  solver.setup();
  while (solver.time() < p.end_time * (1 - 1e-12))
    solver.advance(std::min(solver.next_time_step(), p.end_time - solver.time()));
  const FeDiagnostics d = solver.diagnostics();
  EXPECT_GT(solver.step_number(), 10u);
  EXPECT_NEAR(solver.time(), 1e-3, 1e-12);
  EXPECT_GT(d.kinetic_energy + d.strain_energy, 0.0);
  // Energy balance: work of the traction = kinetic + strain energy (no dissipation); the
  // central difference scheme conserves it to O(dt^2), 2 % at this step.
  EXPECT_NEAR(d.kinetic_energy + d.strain_energy, d.external_work, 0.02 * d.external_work);
  EXPECT_EQ(d.n_failed_points, 0u);
}

// The output mesh gathered from two ranks holds every node once, at its reference position
// plus its displacement as the solver reports it node by node, and every hexahedron in
// XDMF's corner order has a positive volume.
TEST(FeMeshOutput, GathersEveryNodeOnceWithItsDisplacement)
{
  const FeSceneParameters p = holed_slab(TimeIntegrator::central_difference);
  const Snapshot world = run(p, MPI_COMM_WORLD, 40);
  const Snapshot self = run(p, MPI_COMM_SELF, 40);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
  {
    EXPECT_TRUE(world.mesh.positions.empty());
    return;
  }
  const FeMeshForOutput& mesh = world.mesh;
  const std::size_t n_vertices = mesh.positions.size() / 3, n_cells = mesh.failure.size();
  ASSERT_EQ(n_vertices, self.displacement.size()); // linear elements: the nodes are the vertices
  ASSERT_EQ(n_vertices, self.mesh.positions.size() / 3);
  ASSERT_EQ(mesh.hexahedra.size(), 8 * n_cells);
  ASSERT_EQ(mesh.stress.size(), 6 * n_cells);
  EXPECT_EQ(n_cells, self.mesh.failure.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < n_vertices; ++i)
  {
    std::array<long, 3> key;
    Tensor<1, 3> u;
    for (unsigned int c = 0; c < 3; ++c)
    {
      u[c] = mesh.displacement[3 * i + c];
      key[c] = std::lround((mesh.positions[3 * i + c] - u[c]) * 1e6);
    }
    const auto node = self.displacement.find(key);
    ASSERT_NE(node, self.displacement.end()) << "vertex " << i << " is no node of the mesh";
    EXPECT_LT((node->second - u).norm(), 1e-12 * node->second.norm() + 1e-18);
    largest = std::max(largest, u.norm());
  }
  EXPECT_GT(largest, 0.0);
  std::set<std::uint32_t> ranks(mesh.rank.begin(), mesh.rank.end());
  EXPECT_EQ(ranks.size(), Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
  for (std::size_t k = 0; k < n_cells; ++k)
  {
    Tensor<1, 3> corner[8];
    for (unsigned int j = 0; j < 8; ++j)
      for (unsigned int c = 0; c < 3; ++c)
        corner[j][c] = mesh.positions[3 * mesh.hexahedra[8 * k + j] + c];
    // XDMF order: 0 1 2 3 round the bottom, 4 above 0: edges 0-1, 0-3, 0-4 form a right hand.
    const double volume =
        cross_product_3d(corner[1] - corner[0], corner[3] - corner[0]) * (corner[4] - corner[0]);
    EXPECT_GT(volume, 0.0) << "cell " << k;
  }
}

// A far-field failure found on one rank reaches every rank in that rank's words: the others,
// whose cells were fine, have none of their own to give (they used to report "failure on
// another MPI rank: " and nothing after it).
TEST(FeFailure, EveryRankReportsTheFailingRanksMessage)
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  for (const std::string& words : {std::string("FE: an inverted cell"), std::string()})
  {
    std::string what;
    try
    {
      throw_if_any(rank == 0, words, MPI_COMM_WORLD);
    }
    catch (const std::runtime_error& e)
    {
      what = e.what();
    }
    // EXPECT, not ASSERT: a rank leaving the loop early would leave the other in a collective.
    EXPECT_FALSE(what.empty()) << "rank " << rank << " did not throw, or threw no words";
    if (!words.empty())
    {
      EXPECT_NE(what.find(words), std::string::npos) << what;
    }
    if (rank != 0)
    {
      EXPECT_NE(what.find("on MPI rank 0"), std::string::npos) << what;
    }
  }
  // Nobody failed: nobody throws.
  EXPECT_NO_THROW(throw_if_any(false, "", MPI_COMM_WORLD));
}
} // namespace
