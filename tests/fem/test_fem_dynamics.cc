// Dynamics verification: a plane wave in a bar against d'Alembert's solution (arrival time,
// amplitude, error under refinement, explicit and implicit), energy conservation of Newmark
// and high-frequency-only dissipation of generalized-alpha in a free vibration.
#include "fem/far_field_solver.h"
#include "fem_test_scenes.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <iostream>

namespace
{
using namespace dealii;
using namespace vulnus;
using namespace vulnus::fem;
using vulnus::fem::testing::bar;

constexpr double bar_length = 0.1; // m
constexpr double density = 1060.0;

struct WaveResult
{
  double l2_error = 0.0;        ///< relative, of v_x along the bar at the end time
  double peak_time_error = 0.0; ///< s, at mid-bar, peak by parabolic fit
  double peak_amplitude = 0.0;  ///< relative to the imposed amplitude
  double pulse_duration = 0.0;
};

/// A sine-squared velocity pulse of duration 0.2 L / c imposed at x = 0; run to 0.65 L / c.
WaveResult plane_wave(const TimeIntegrator integrator, const unsigned int n_cells,
                      const double courant, const bool one_point)
{
  FeSceneParameters p = bar(bar_length, n_cells);
  p.one_point_integration = one_point;
  const double c = vulnus::fem::testing::p_wave_speed(p.material, density);
  const double amplitude = 1e-6 * c; // strain amplitude 1e-6: linear regime
  const double duration = 0.2 * bar_length / c;
  p.faces[0].condition = FaceParameters::Condition::velocity;
  p.faces[0].value = {{amplitude, 0.0, 0.0}};
  p.faces[0].profile = {TimeProfile::Kind::sine_squared, duration};
  p.integrator = integrator;
  p.cfl = courant;
  p.time_step = courant * (bar_length / n_cells) / c;
  p.newton_relative_tolerance = 1e-10;
  FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();

  const double end_time = 0.65 * bar_length / c;
  const NodeRecord* probe = nullptr;
  for (const NodeRecord& node : solver.locally_owned_nodes())
    if (node.position[1] < 1e-9 && node.position[2] < 1e-9 &&
        (probe == nullptr || std::abs(node.position[0] - 0.5 * bar_length) <
                                 std::abs(probe->position[0] - 0.5 * bar_length)))
      probe = &node;
  EXPECT_NE(probe, nullptr);
  const double x_probe = probe->position[0];
  std::vector<double> times{0.0}, probe_v{0.0};
  while (solver.time() < end_time * (1 - 1e-12))
  {
    solver.advance(std::min(solver.next_time_step(), end_time - solver.time()));
    times.push_back(solver.time());
    probe_v.push_back(solver.velocity(*probe)[0]);
  }

  WaveResult r;
  r.pulse_duration = duration;
  const double t = solver.time();
  const TimeProfile pulse = p.faces[0].profile;
  double error = 0.0, norm = 0.0;
  for (const NodeRecord& node : solver.locally_owned_nodes())
  {
    const double exact = amplitude * pulse.value(t - node.position[0] / c);
    error += std::pow(solver.velocity(node)[0] - exact, 2);
    norm += exact * exact;
  }
  r.l2_error = std::sqrt(error / norm);
  std::size_t k = 1;
  for (std::size_t i = 1; i + 1 < probe_v.size(); ++i)
    if (probe_v[i] > probe_v[k])
      k = i;
  // Parabola through the three samples around the maximum.
  const double t0 = times[k - 1], t1 = times[k], t2 = times[k + 1];
  const double v0 = probe_v[k - 1], v1 = probe_v[k], v2 = probe_v[k + 1];
  const double denominator = (t0 - t1) * (t0 - t2) * (t1 - t2);
  const double A = (t2 * (v1 - v0) + t1 * (v0 - v2) + t0 * (v2 - v1)) / denominator;
  const double B = (t2 * t2 * (v0 - v1) + t1 * t1 * (v2 - v0) + t0 * t0 * (v1 - v2)) / denominator;
  const double C = v0 - A * t0 * t0 - B * t0;
  const double t_peak = -B / (2 * A);
  r.peak_time_error = t_peak - (x_probe / c + 0.5 * duration);
  r.peak_amplitude = (C + B * t_peak + A * t_peak * t_peak) / amplitude;
  return r;
}

struct WaveCase
{
  TimeIntegrator integrator;
  double courant;
  const char* name;
  bool one_point = false;
};

class PlaneWave : public ::testing::TestWithParam<WaveCase>
{
};

TEST_P(PlaneWave, MatchesDAlembertAndConvergesUnderRefinement)
{
  const WaveCase w = GetParam();
  const unsigned int levels[4] = {25, 50, 100, 200};
  double errors[4];
  for (unsigned int l = 0; l < 4; ++l)
  {
    const WaveResult r = plane_wave(w.integrator, levels[l], w.courant, w.one_point);
    errors[l] = r.l2_error;
    std::cout << "[plane wave " << w.name << "] cells " << levels[l] << "  L2 error " << r.l2_error
              << "  peak time error " << r.peak_time_error / r.pulse_duration
              << " pulse durations  peak amplitude " << r.peak_amplitude << std::endl;
    if (l == 3)
    {
      EXPECT_LT(std::abs(r.peak_time_error), 0.005 * r.pulse_duration);
      EXPECT_NEAR(r.peak_amplitude, 1.0, 0.01);
      EXPECT_LT(r.l2_error, 0.015);
    }
  }
  std::cout << "[plane wave " << w.name << "] observed rates";
  for (unsigned int l = 0; l + 1 < 4; ++l)
    std::cout << ' ' << std::log2(errors[l] / errors[l + 1]);
  std::cout << std::endl;
  // Observed 1.81 (explicit) and 1.79 (Newmark): second order, slowed by the sin^2 pulse,
  // whose second derivative jumps at its start and end.
  EXPECT_GT(std::log2(errors[2] / errors[3]), 1.7);
}

INSTANTIATE_TEST_SUITE_P(Integrators, PlaneWave,
                         ::testing::Values(WaveCase{TimeIntegrator::central_difference, 0.5,
                                                    "explicit"},
                                           WaveCase{TimeIntegrator::newmark, 0.5, "newmark"},
                                           WaveCase{TimeIntegrator::central_difference, 0.5,
                                                    "explicit_one_point", true}),
                         [](const ::testing::TestParamInfo<WaveCase>& info)
                         { return std::string(info.param.name); });

/// The plane wave's pulse a third of the way along the bar, with cells at rest skipped or
/// not: the skipped run must have skipped the cells ahead of the front and agree with the
/// full evaluation to far below the wave (the skipped cells' strains are below 1e-12).
TEST(QuietCells, SkippingCellsAtRestChangesNothingButTheirCost)
{
  struct Run
  {
    std::vector<double> u, v;
    double strain_energy = 0.0;
    unsigned long long skipped = 0;
  };
  const unsigned int n_cells = 100;
  auto run = [&](const bool skip)
  {
    FeSceneParameters p = bar(bar_length, n_cells);
    const double c = vulnus::fem::testing::p_wave_speed(p.material, density);
    p.faces[0].condition = FaceParameters::Condition::velocity;
    p.faces[0].value = {{1e-3 * c, 0.0, 0.0}};
    p.faces[0].profile = {TimeProfile::Kind::sine_squared, 0.1 * bar_length / c};
    p.skip_quiet_cells = skip;
    FarFieldSolver solver(p, MPI_COMM_SELF);
    solver.setup();
    const double end_time = 0.35 * bar_length / c;
    while (solver.time() < end_time * (1 - 1e-12))
      solver.advance(std::min(solver.next_time_step(), end_time - solver.time()));
    Run r;
    for (const NodeRecord& node : solver.locally_owned_nodes())
    {
      r.u.push_back(solver.displacement(node)[0]);
      r.v.push_back(solver.velocity(node)[0]);
    }
    r.strain_energy = solver.diagnostics().strain_energy;
    r.skipped = solver.explicit_phase_times().quiet_cells_skipped;
    return r;
  };
  const Run full = run(false), skipping = run(true);
  EXPECT_EQ(full.skipped, 0u);
  // The front (pulse 0.1 L behind it) reaches 0.35 L: about half of the cells ahead stay
  // quiet over the run, summed over its steps.
  EXPECT_GT(skipping.skipped, 20u * n_cells);
  double u_max = 0.0, v_max = 0.0, du = 0.0, dv = 0.0;
  for (std::size_t i = 0; i < full.u.size(); ++i)
  {
    u_max = std::max(u_max, std::abs(full.u[i]));
    v_max = std::max(v_max, std::abs(full.v[i]));
    du = std::max(du, std::abs(full.u[i] - skipping.u[i]));
    dv = std::max(dv, std::abs(full.v[i] - skipping.v[i]));
  }
  std::cout << "[quiet cells] skipped " << skipping.skipped << " cell evaluations; largest change u "
            << du / u_max << ", v " << dv / v_max << " of the largest" << std::endl;
  // A skipped cell's nodes have moved at most 1e-12 h (1e-15 m here) against the pulse's
  // 5e-6 m: changes of order 2e-10 of the wave (seen: 1.6e-10 in u, 4.2e-10 in v).
  EXPECT_LT(du, 1e-9 * u_max);
  EXPECT_LT(dv, 1e-9 * v_max);
  EXPECT_NEAR(skipping.strain_energy, full.strain_energy, 1e-10 * full.strain_energy);
}

/// The force evaluation and the implicit step's Newton systems share the cells among threads
/// and add their work in cell order: a graded slab around a hole whose walls are dragged along
/// must reach the same state bit for bit on 1 and 2 threads (cells of one nominal size differ
/// in the last bits, so the values may not depend on which cell a thread saw before).
struct ThreadCase
{
  TimeIntegrator integrator;
  bool one_point;
  const char* name;
};

class FarFieldThreads : public ::testing::TestWithParam<ThreadCase>
{
};

TEST_P(FarFieldThreads, SameStateBitForBitOnAnyThreadCount)
{
  const bool implicit = GetParam().integrator != TimeIntegrator::central_difference;
  unsigned int setups = 0, solves = 0;
  auto run = [&](const int threads)
  {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    FeSceneParameters p;
    p.integrator = GetParam().integrator;
    p.one_point_integration = GetParam().one_point;
    p.time_step = 2e-5; // implicit: about 10 explicit steps
    p.has_hole = true;
    p.hole_min = {{0.02, 0.0, 0.02}};
    p.hole_max = {{0.03, 0.01, 0.03}};
    p.interface_cell_size = 1e-3;
    p.far_cell_size = 2e-3;
    p.grading_ratio = 1.15;
    p.interface_condition = InterfaceCondition::velocity_driven;
    FarFieldSolver solver(p, MPI_COMM_SELF);
    solver.setup();
    std::vector<dealii::Tensor<1, 3>> v(solver.interface_nodes().size());
    for (auto& w : v)
      w[1] = 0.5; // m/s along the hole's axis
    solver.set_interface_velocities(v);
    setups = solves = 0;
    for (int step = 0; step < (implicit ? 3 : 20); ++step)
    {
      solver.advance(solver.next_time_step());
      if (implicit)
      {
        setups += solver.last_implicit_step().preconditioner_setups;
        solves += solver.last_implicit_step().newton_iterations;
      }
    }
    std::vector<double> state;
    for (const NodeRecord& node : solver.locally_owned_nodes())
      for (unsigned int c = 0; c < 3; ++c)
        state.insert(state.end(), {solver.displacement(node)[c], solver.velocity(node)[c]});
    state.push_back(solver.diagnostics().strain_energy);
    omp_set_num_threads(before);
    return state;
  };
  const std::vector<double> one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_GT(std::abs(one.back()), 0.0); // the walls have strained the slab
  std::size_t differing = 0;
  for (std::size_t i = 0; i < one.size(); ++i)
    differing += one[i] != two[i];
  EXPECT_EQ(differing, 0u);
  if (implicit)
  {
    // One multigrid hierarchy serves the steps of one length (Far field/Reuse preconditioner).
    std::cout << "[implicit threads] " << solves << " Newton solves, " << setups
              << " multigrid set-ups" << std::endl;
    EXPECT_GE(solves, 3u);
    EXPECT_EQ(setups, 1u);
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, FarFieldThreads,
                         ::testing::Values(ThreadCase{TimeIntegrator::central_difference, false,
                                                      "explicit"},
                                           ThreadCase{TimeIntegrator::newmark, false, "newmark"},
                                           ThreadCase{TimeIntegrator::central_difference, true,
                                                      "explicit_one_point"}),
                         [](const auto& info) { return std::string(info.param.name); });

/// Free vibration of a fixed-fixed bar (uniaxial strain) from an initial velocity of mode
/// `mode` (sin(mode pi x / L); mode = n_cells gives the node-to-node alternating field,
/// the highest mode). Returns the total energy after each step over the initial.
std::vector<double> free_vibration(const TimeIntegrator integrator, const double rho_inf,
                                   const unsigned int n_cells, const unsigned int mode,
                                   const unsigned int n_steps, const double dt,
                                   const LinearSolverType linear_solver = LinearSolverType::cg)
{
  FeSceneParameters p = bar(bar_length, n_cells);
  p.integrator = integrator;
  p.linear_solver = linear_solver;
  p.spectral_radius = rho_inf;
  p.time_step = dt;
  p.newton_relative_tolerance = 1e-11;
  FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();
  const double c = vulnus::fem::testing::p_wave_speed(p.material, density);
  const double amplitude = 1e-5 * c;
  const double h = bar_length / n_cells;
  solver.set_initial_velocity(
      [&](const Point<3>& x)
      {
        Tensor<1, 3> v;
        if (mode == n_cells)
          v[0] = amplitude * ((static_cast<long>(std::lround(x[0] / h)) % 2 == 0) ? 1.0 : -1.0);
        else
          v[0] = amplitude * std::sin(mode * M_PI * x[0] / bar_length);
        return v;
      });
  const FeDiagnostics d0 = solver.diagnostics();
  const double e0 = d0.kinetic_energy + d0.strain_energy;
  std::vector<double> ratio;
  for (unsigned int s = 0; s < n_steps; ++s)
  {
    solver.advance(dt);
    const FeDiagnostics d = solver.diagnostics();
    ratio.push_back((d.kinetic_energy + d.strain_energy) / e0);
  }
  return ratio;
}

TEST(Energy, NewmarkConservesTotalEnergyOfFreeVibration)
{
  const unsigned int n = 40;
  const double c =
      vulnus::fem::testing::p_wave_speed(vulnus::fem::testing::elastic_isotropic(), density);
  const double period = 2.0 * bar_length / c; // mode 1 of the fixed-fixed bar
  const double dt = period / 40.0;
  for (const unsigned int mode : {1u, n})
  {
    const std::vector<double> e = free_vibration(TimeIntegrator::newmark, 1.0, n, mode, 80, dt);
    double worst = 0.0;
    for (const double x : e)
      worst = std::max(worst, std::abs(x - 1.0));
    std::cout << "[energy newmark] mode " << mode << ": max |E/E0 - 1| over 80 steps = " << worst
              << std::endl;
    EXPECT_LT(worst, 1e-6);
  }
}

// Far field/Linear solver = direct: the Newton corrections by a sparse LU instead of CG to
// 1e-10 of the residual. Both histories stop Newton at 1e-11 of the force scale, which leaves
// each a conservation error of about 1e-7 of E0 (measured: 1.1e-7; they differ by 7e-8): the
// same energy history within the conservation test's bound, and conserved as well.
TEST(Energy, NewmarkWithTheDirectSolverFollowsTheKrylovOne)
{
  const unsigned int n = 40;
  const double c =
      vulnus::fem::testing::p_wave_speed(vulnus::fem::testing::elastic_isotropic(), density);
  const double dt = 2.0 * bar_length / c / 40.0;
  const std::vector<double> krylov = free_vibration(TimeIntegrator::newmark, 1.0, n, 1, 80, dt);
  const std::vector<double> direct =
    free_vibration(TimeIntegrator::newmark, 1.0, n, 1, 80, dt, LinearSolverType::direct);
  ASSERT_EQ(krylov.size(), direct.size());
  double worst_difference = 0.0, worst_drift = 0.0;
  for (std::size_t i = 0; i < direct.size(); ++i)
  {
    worst_difference = std::max(worst_difference, std::abs(direct[i] - krylov[i]));
    worst_drift = std::max(worst_drift, std::abs(direct[i] - 1.0));
  }
  std::cout << "[direct newmark] max |E_direct - E_cg| / E0 = " << worst_difference
            << ", max |E/E0 - 1| = " << worst_drift << std::endl;
  EXPECT_LT(worst_difference, 1e-6);
  EXPECT_LT(worst_drift, 1e-6);
}

TEST(Energy, GeneralizedAlphaDampsOnlyHighFrequencies)
{
  const unsigned int n = 40;
  const double c =
      vulnus::fem::testing::p_wave_speed(vulnus::fem::testing::elastic_isotropic(), density);
  const double period = 2.0 * bar_length / c;
  const double dt = period / 40.0;
  const std::vector<double> low =
      free_vibration(TimeIntegrator::generalized_alpha, 0.5, n, 1, 40, dt);
  const std::vector<double> high =
      free_vibration(TimeIntegrator::generalized_alpha, 0.5, n, n, 20, dt);
  std::cout << "[energy generalized-alpha rho_inf 0.5] mode 1 after one period E/E0 = "
            << low.back() << "; highest mode after 20 steps E/E0 = " << high.back() << std::endl;
  EXPECT_GT(low.back(), 0.99);
  EXPECT_LT(high.back(), 1e-3);
}
} // namespace

namespace
{
/// A far field almost at rest, as in a hybrid run before the wave reaches it: strains of
/// 1e-13, where F = I + grad u keeps only three significant digits of them, so the residual
/// cannot fall by the relative tolerance. The steps are converged to round-off and must be
/// accepted, not reported as Newton failures, and the tiny vibration must still be right.
TEST(Newton, AcceptsStepsWhoseStrainsAreAtRoundOff)
{
  FeSceneParameters p = bar(bar_length, 20);
  p.integrator = TimeIntegrator::newmark;
  const double c = vulnus::fem::testing::p_wave_speed(p.material, density);
  const double period = 2.0 * bar_length / c; // mode 1 of the fixed-fixed bar
  p.time_step = period / 8.0;
  FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();
  solver.set_initial_velocity(
      [&](const Point<3>& x)
      {
        Tensor<1, 3> v;
        v[0] = 1e-13 * c * std::sin(M_PI * x[0] / bar_length);
        return v;
      });
  // Kinetic energy only: the strain energy of F this close to I has a round-off floor of
  // about c1 * 1e-16 per unit volume, far above this vibration's energy.
  const double e0 = solver.diagnostics().kinetic_energy;
  std::vector<double> kinetic;
  for (int s = 0; s < 4; ++s)
  {
    EXPECT_NO_THROW(solver.advance(p.time_step)) << "step " << s;
    kinetic.push_back(solver.diagnostics().kinetic_energy);
    EXPECT_LE(kinetic.back(), 1.001 * e0) << "step " << s;
  }
  // A quarter period: all strain; half a period: all kinetic again, within Newmark's period
  // error at omega dt = pi / 4 ((omega dt)^2 / 12 = 5 %).
  EXPECT_LT(kinetic[1], 0.05 * e0);
  EXPECT_GT(kinetic[3], 0.95 * e0);
}

/// A step whose predicted state already inverts a cell (the bar's end pushed 1.5 cells in one
/// short step) fails before Newton has a residual: the message must say so, not report "0
/// Newton iterations (residual 0 N, first 0 N)".
TEST(Newton, AStepFailingAtItsPredictorSaysSo)
{
  FeSceneParameters p = bar(bar_length, 10);
  p.integrator = TimeIntegrator::newmark;
  p.faces[0].condition = FaceParameters::Condition::velocity;
  p.faces[0].value = {{300.0, 0.0, 0.0}};
  p.time_step = 1e-4; // below two wave transits of a cell: the step extrapolates its predictor
  FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();
  std::string what;
  try
  {
    solver.advance(p.time_step);
  }
  catch (const std::runtime_error& e)
  {
    what = e.what();
  }
  EXPECT_NE(what.find("the cells could not be evaluated at the step's predicted state"),
            std::string::npos)
    << what;
  EXPECT_NE(what.find("inverted"), std::string::npos) << what;
  EXPECT_EQ(what.find("0 Newton iterations"), std::string::npos) << what;
  EXPECT_EQ(what.find("residual 0 N"), std::string::npos) << what;
}
} // namespace

namespace
{
/// A free 6 mm cube of 1 mm cells, nearly incompressible (bulk:shear 1e4, cell J), started
/// with a velocity that differs at every node (every mode excited, hourglass modes among
/// them), run for 1,500 explicit steps.
struct RoughStart
{
  double worst_energy_change = 0.0; ///< largest |E / E0 - 1|
  std::vector<double> velocities;   ///< at the end, node by node
};

RoughStart rough_start(const bool one_point, const double amplitude)
{
  FeSceneParameters p;
  p.slab_min = {{0.0, 0.0, 0.0}};
  p.slab_max = {{0.006, 0.006, 0.006}};
  p.interface_cell_size = p.far_cell_size = 0.001;
  p.material = vulnus::fem::testing::elastic_isotropic();
  p.material.tissue.bulk_modulus = 1e4 * 2.0 * p.material.tissue.c1;
  p.volume_averaging = true;
  p.one_point_integration = one_point;
  for (auto& face : p.faces)
    face.condition = FaceParameters::Condition::free;
  FarFieldSolver solver(p, MPI_COMM_SELF);
  solver.setup();
  solver.set_initial_velocity(
      [&](const Point<3>& x)
      {
        Tensor<1, 3> v;
        for (unsigned int c = 0; c < 3; ++c)
          v[c] = amplitude * std::sin(1e4 * (x[0] + 2.3 * x[1] + 3.7 * x[2]) + 1.9 * c);
        return v;
      });
  const FeDiagnostics d0 = solver.diagnostics();
  const double e0 = d0.kinetic_energy + d0.strain_energy;
  RoughStart r;
  for (int s = 0; s < 1500; ++s)
  {
    solver.advance(solver.next_time_step());
    const FeDiagnostics d = solver.diagnostics();
    r.worst_energy_change =
      std::max(r.worst_energy_change, std::abs((d.kinetic_energy + d.strain_energy) / e0 - 1.0));
  }
  for (const NodeRecord& node : solver.locally_owned_nodes())
    for (unsigned int c = 0; c < 3; ++c)
      r.velocities.push_back(solver.velocity(node)[c]);
  return r;
}

/// On box cells and at small strain, one point with the hourglass stiffness is the full F-bar
/// element (fem/hourglass.h): a rough start, every mode excited, must ring the same way node
/// by node, and the hourglass energy (u . mu S u / 2, booked as strain energy) must keep the
/// total as the full element does. What differs is the laws' nonlinearity, first order in
/// the amplitude (measured: 3.4e-4 of the largest velocity at 1 mm/s, 3.4e-5 at 0.1 mm/s).
TEST(OnePointCells, RoughStartRingsAsTheFullElementDoes)
{
  double relative[2] = {0.0, 0.0};
  for (const int k : {0, 1})
  {
    const double amplitude = k == 0 ? 1e-3 : 1e-4; // m/s
    const RoughStart full = rough_start(false, amplitude), one = rough_start(true, amplitude);
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < full.velocities.size(); ++i)
    {
      difference = std::max(difference, std::abs(one.velocities[i] - full.velocities[i]));
      norm = std::max(norm, std::abs(full.velocities[i]));
    }
    relative[k] = difference / norm;
    std::cout << "[rough start, " << amplitude << " m/s] max |E/E0 - 1| over 1,500 steps: full "
              << full.worst_energy_change << ", one point " << one.worst_energy_change
              << "; velocities differ by " << relative[k] << " of the largest" << std::endl;
    EXPECT_LT(one.worst_energy_change, 0.02);
    EXPECT_LT(one.worst_energy_change, 1.01 * full.worst_energy_change);
  }
  EXPECT_LT(relative[1], 1e-4);
  EXPECT_NEAR(relative[0] / relative[1], 10.0, 2.0); // first order in the amplitude
}
} // namespace
