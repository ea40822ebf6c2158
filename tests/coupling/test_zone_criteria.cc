// The adaptive zone's criteria on what a far-field cell cannot carry: a block moving rigidly
// past a tenth of a cell converts under the whole-displacement rule and not under the
// non-affine one (rigid motion is affine over every cell); a block sheared uniformly converts
// under the distortion bound and under nothing else; each conversion records which rule
// asked for it; a block sheared past the matrix's failure converts under the any-failure
// rule, and under the total-failure rule the far field carries the failed matrix with the
// stress the MPM points in the same state carry, and gives the wound figures its failed
// tissue on the MPM lattice.
#include "coupling/hybrid_solver.h"
#include "materials/material_registry.h"
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
                                           AdaptiveZoneParameters rules,
                                           const materials::MaterialParameters* material = nullptr)
{
  const double h = 1e-3;
  mpm::SceneParameters s = block_scene({0, 0, 0}, {0.012, 0.012, 0.012}, h);
  if (material)
  {
    s.materials[0].parameters = *material;
    // Room for a shear's points to move along x.
    s.domain_min[0] -= 0.004;
    s.domain_max[0] += 0.004;
  }
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

// The paper's tissue with its failure, fibers along x, sheared at 1000/s in the x-y plane
// about the block's centre (the fibers keep their length) and compressed at 100/s along z:
// the matrix shear bound reaches its limit about 0.45 ms in, and by 0.6 ms every point's
// matrix has failed and carries the compressed volume's pressure alone.
TEST(ZoneCriteria, MatrixFailureConvertsUnderTheAnyRuleAndStaysInTheFarFieldUnderTheTotalRule)
{
  materials::MaterialParameters tissue;
  tissue.model = "transversely isotropic hyperelastic";
  Eigen::Matrix3d L = Eigen::Matrix3d::Zero();
  L(0, 1) = 1000.0;
  L(2, 2) = -100.0;
  AdaptiveZoneParameters rules;
  rules.threshold = 1.0;
  rules.interface_motion = InterfaceMotion::non_affine;
  rules.failure = fem::FailureProximity::any_failure;
  // About the block's centre, so that its points stay within the grid's 4 mm margin in x.
  const Eigen::Vector3d v0 = -L * Eigen::Vector3d(0.006, 0.006, 0.006);
  auto any = moving_block(v0, L, rules, &tissue);
  run_to(*any, 6e-4);
  ASSERT_FALSE(any->conversions().empty());
  EXPECT_GT(flagged(*any, ZoneCause::failure), 0u);

  // The distortion bound the total rule needs, above the shear's ln(1.34 / 0.74) = 0.59.
  rules.failure = fem::FailureProximity::total_failure;
  rules.distortion = 1.0;
  auto total = moving_block(v0, L, rules, &tissue);
  run_to(*total, 6e-4);
  EXPECT_TRUE(total->conversions().empty());
  const fem::FarFieldSolver& fe = total->fe();
  EXPECT_EQ(fe.n_failed_points(), 0u) << "no point failed beyond what the far field carries";

  // Where the far field moves as its faces drive it, F = I + L t; the shared law's
  // matrix-failed point carries there the compressed volume's pressure alone.
  const std::unique_ptr<materials::Material> law = materials::create_material(tissue);
  materials::PointState failed;
  failed.failure = materials::matrix_failed;
  materials::PointResponse expected;
  law->update(Eigen::Matrix3d::Identity() + total->time() * L, Eigen::Vector3d::UnitX(), failed,
              expected);
  const double pressure = -expected.cauchy_stress.trace() / 3.0;
  ASSERT_GT(pressure, 1e4) << "the compression should leave a pressure to compare";
  ASSERT_LT((expected.cauchy_stress + pressure * Eigen::Matrix3d::Identity()).norm(),
            1e-9 * pressure);

  // Waves from the zone's boundary disturb the affine motion; the cells whose stress is a
  // pressure alone (no fiber stretched, every point failed) carry the law's, on average.
  const fem::FeMeshForOutput mesh = fe.mesh_for_output();
  std::size_t matrix_failed_cells = 0, pressure_only = 0;
  double fe_pressure = 0.0;
  for (std::size_t c = 0; c < mesh.failure.size(); ++c)
  {
    ASSERT_TRUE(mesh.failure[c] == materials::intact ||
                mesh.failure[c] == materials::matrix_failed)
      << "cell " << c << " flag " << int(mesh.failure[c]);
    if (mesh.failure[c] != materials::matrix_failed)
      continue;
    ++matrix_failed_cells;
    const Eigen::Map<const Eigen::Matrix<double, 6, 1>> voigt(&mesh.stress[6 * c]);
    const double p = -(voigt[0] + voigt[1] + voigt[2]) / 3.0;
    const double deviator = std::sqrt((voigt.head<3>().array() + p).square().sum() +
                                      2.0 * voigt.tail<3>().squaredNorm());
    if (deviator <= 1e-6 * p)
    {
      ++pressure_only;
      fe_pressure += p;
    }
  }
  EXPECT_GT(matrix_failed_cells, 0.95 * mesh.failure.size());
  ASSERT_GT(pressure_only, 0.25 * matrix_failed_cells);

  // The wound figures count the far field's failed tissue as its conversion would make it:
  // 2 x 2 x 2 lattice points per 1 mm cell, each matrix-failed where its octant's Gauss point
  // is, together the volume of the failed octants (at most the failed cells', and all of it
  // where every Gauss point of a failed cell has failed).
  const double h = 1e-3;
  const std::vector<fem::FailedLatticePoint> lattice = fe.failed_lattice_points(0.5 * h);
  double lattice_volume = 0.0;
  for (const fem::FailedLatticePoint& p : lattice)
  {
    ASSERT_EQ(p.failure, materials::matrix_failed);
    ASSERT_NEAR(p.reference_volume, 0.125 * h * h * h, 1e-12 * h * h * h);
    lattice_volume += p.reference_volume;
  }
  EXPECT_LE(lattice_volume, matrix_failed_cells * h * h * h * (1.0 + 1e-12));
  EXPECT_GT(lattice_volume, 0.9 * matrix_failed_cells * h * h * h);
  // Each carries its cell's stress, so the wound's debris (a pressure alone) is the cells'.
  std::size_t pressure_only_points = 0;
  for (const fem::FailedLatticePoint& p : lattice)
  {
    const double mean = dealii::trace(p.cell_stress) / 3.0;
    const double deviator = (p.cell_stress - mean * dealii::unit_symmetric_tensor<3>()).norm();
    pressure_only_points += deviator <= 1e-6 * std::abs(mean) ? 1 : 0;
  }
  EXPECT_GT(pressure_only_points, 0u);
  EXPECT_LE(pressure_only_points, 8 * pressure_only);
  EXPECT_NEAR(fe_pressure / pressure_only, pressure, 0.02 * pressure);

  // The MPM zone's matrix-failed points, under the same law, carry the same mean pressure
  // within their noise (their failure released the matrix's stress at once). Both bounds are
  // measured margins: 1.4 % for the far field's cells, 6.4 % for the points.
  const mpm::Particles& points = total->mpm().points();
  double mpm_pressure = 0.0;
  std::size_t n_matrix_failed = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
    if (points.failure[p] == materials::matrix_failed)
    {
      ++n_matrix_failed;
      mpm_pressure -= points.stress[p].head<3>().sum() / 3.0;
    }
  ASSERT_GT(n_matrix_failed, 0.9 * points.size());
  EXPECT_NEAR(mpm_pressure / n_matrix_failed, pressure, 0.1 * pressure);
}
} // namespace vulnus::coupling
