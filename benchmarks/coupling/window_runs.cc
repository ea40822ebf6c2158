// The struck block and the plane wave through an MPM zone, run with given coupling windows.
#include "benchmarks/coupling/window_runs.h"

#include "coupling/hybrid_solver.h"
#include "tests/coupling/hybrid_test_scenes.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

namespace vulnus::verification
{
namespace
{
using coupling::testing::block_scene;
using coupling::testing::uniform_far_field;
using coupling::testing::zone;

double seconds_since(const std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void apply_windows(const WindowSettings& windows, coupling::HybridParameters& hybrid,
                   fem::FeSceneParameters& far)
{
  hybrid.substeps = windows.substeps;
  if (windows.dashpot)
    hybrid.window_coupling = coupling::WindowCoupling::dashpot;
  far.integrator = windows.integrator;
}

WindowBooks books_of(const coupling::HybridSolver& solver, const double energy_scale,
                     const double momentum_scale)
{
  const coupling::InterfaceLedger& ledger = solver.ledger();
  WindowBooks b;
  b.created_momentum =
    (ledger.mpm_impulse + ledger.fe_impulse + solver.impulse_in_transit()).norm() / momentum_scale;
  b.interface_energy_error = ledger.energy_error() / energy_scale;
  b.mpm_steps = ledger.mpm_steps;
  b.fe_steps = ledger.fe_steps;
  b.windows_shortened = ledger.windows_shortened;
  b.far_field_resteps = ledger.balance_solves;
  b.effective_mass_seconds = ledger.balance_matrix_seconds;
  return b;
}

// Plane-wave bar: 1 mm cells, 100 mm long, MPM from 30 to 60 mm, a pulse 20 mm long.
constexpr double h = 1e-3;
constexpr double bar_length = 0.1;
constexpr double zone_start = 0.03, zone_end = 0.06;
constexpr double pulse_length = 0.02;   // c T
constexpr double pulse_velocity = 0.01; // m/s, peak particle velocity (small strain)

/// x velocity of the FE nodes beyond the zone, by node position, from all ranks. Collective.
std::vector<std::pair<double, double>> right_part_velocities(const fem::FarFieldSolver& fe)
{
  std::vector<double> mine; // x, v pairs
  for (const fem::NodeRecord& node : fe.locally_owned_nodes())
    if (node.position[0] > zone_end + 0.5 * h && node.position[1] < 0.5 * h &&
        node.position[2] < 0.5 * h)
      mine.insert(mine.end(), {node.position[0], fe.velocity(node)[0]});
  std::vector<std::pair<double, double>> all;
  for (const std::vector<double>& part :
       dealii::Utilities::MPI::all_gather(fe.communicator(), mine))
    for (std::size_t i = 0; i + 1 < part.size(); i += 2)
      all.emplace_back(part[i], part[i + 1]);
  std::sort(all.begin(), all.end());
  return all;
}
} // namespace

StruckBlockResult run_struck_block(const WindowSettings& windows, const double end_time)
{
  const auto start = std::chrono::steady_clock::now();
  const double cell = 1e-3, L = 0.012, c0 = 0.5 * L;
  mpm::SceneParameters s = block_scene({0, 0, 0}, {L, L, L}, cell);
  s.cfl = windows.mpm_cfl;
  coupling::HybridParameters hybrid =
    zone({c0 - 0.002, c0 - 0.002, c0 - 0.002}, {c0 + 0.002, c0 + 0.002, c0 + 0.002},
         coupling::CouplingScheme::multi_step);
  fem::FeSceneParameters far = uniform_far_field(cell);
  apply_windows(windows, hybrid, far);
  far.time_step = 1.0; // the window is set by the substeps
  coupling::HybridScene split = coupling::decompose(s, hybrid, far);
  for (auto& face : split.fe.faces)
    face.condition = fem::FaceParameters::Condition::free;
  coupling::HybridSolver solver(split, MPI_COMM_WORLD);
  // A blow across the interface: a velocity bump centred on the zone's face x = 4 mm.
  solver.set_initial_velocity(
    [c0](const mpm::Vector3& x) -> mpm::Vector3
    {
      const double bump = std::exp(-(x - mpm::Vector3(c0 - 0.002, c0, c0)).squaredNorm() / 4e-6);
      return mpm::Vector3(0.3 * bump, -0.2 * bump, 0.1 * bump);
    });
  const Eigen::Vector3d p0 = solver.total_momentum();
  const double e0 = solver.mpm().diagnostics().kinetic_energy + solver.fe_mechanical_energy();
  const double p_scale = 1000.0 * std::pow(L, 3) * 0.3;
  StruckBlockResult r;
  double e = e0;
  while (solver.time() < end_time)
  {
    solver.advance();
    if (solver.at_window_end())
      r.momentum_drift = std::max(r.momentum_drift, (solver.total_momentum() - p0).norm());
    r.largest_transit = std::max(r.largest_transit, solver.impulse_in_transit().norm());
    const auto d = solver.mpm().diagnostics();
    e = d.kinetic_energy + d.strain_energy + d.dissipated_energy + solver.fe_mechanical_energy();
    r.energy_change = std::max(r.energy_change, std::abs(e - e0));
    r.energy_growth = std::max(r.energy_growth, e - e0);
  }
  r.momentum_drift /= p_scale;
  r.largest_transit /= p_scale;
  r.energy_change /= e0;
  r.energy_growth /= e0;
  r.energy_at_end = (e - e0) / e0;
  r.transits_per_window = windows.substeps * windows.mpm_cfl;
  r.books = books_of(solver, e0, p_scale);
  r.books.seconds = seconds_since(start);
  return r;
}

WaveResult run_wave_through_interface(const coupling::CouplingScheme scheme,
                                      const WindowSettings& windows, const bool convert)
{
  const auto start = std::chrono::steady_clock::now();
  mpm::SceneParameters bar = block_scene({0, 0, 0}, {bar_length, h, h}, h);
  for (int f = 2; f < 6; ++f)
    bar.domain_faces[f] = mpm::FaceCondition::roller;
  bar.cfl = windows.mpm_cfl;
  const double c = coupling::testing::wave_speed(bar.materials[0].parameters, 1000.0);
  const double duration = pulse_length / c;
  coupling::HybridParameters hybrid = zone({zone_start, 0, 0}, {zone_end, h, h}, scheme);
  hybrid.adaptive.enabled = convert;
  hybrid.adaptive.reach = 0.01;
  fem::FeSceneParameters far = uniform_far_field(h);
  if (windows.substeps > 0)
  {
    apply_windows(windows, hybrid, far);
    far.time_step = windows.substeps * windows.mpm_cfl * h / c;
  }
  coupling::HybridScene split = coupling::decompose(bar, hybrid, far);
  fem::FaceParameters& pulse = split.fe.faces[0];
  pulse.condition = fem::FaceParameters::Condition::velocity;
  pulse.value = {pulse_velocity, 0.0, 0.0};
  pulse.profile.kind = fem::TimeProfile::Kind::sine_squared;
  pulse.profile.duration = duration;
  split.fe.faces[1].condition = fem::FaceParameters::Condition::fixed;
  // The pure-FE bar of the same deck: the single-method solution.
  fem::FeSceneParameters whole = split.fe;
  whole.has_hole = false;
  whole.has_focus = false;
  whole.interface_condition = fem::InterfaceCondition::free;
  whole.staggered_velocity = false;
  fem::FarFieldSolver reference(whole, MPI_COMM_WORLD);
  reference.setup();
  // At the step the hybrid's far field takes: implicit windows last at most one wave transit
  // of the smallest cell unless they have a dashpot.
  auto advance_reference_to = [&reference](const double t)
  {
    while (reference.time() < t * (1 - 1e-12))
      reference.advance(std::min({reference.next_time_step(), reference.shortest_wave_transit(),
                                  t - reference.time()}));
  };

  coupling::HybridSolver solver(split, MPI_COMM_WORLD);
  if (convert)
  {
    // Pulse front at the zone (30 mm): its front half lies in the converted part.
    const double t_convert = zone_start / c;
    while (solver.time() < t_convert || !solver.at_window_end())
      solver.advance();
    solver.grow_zone({zone_start - 0.01, 0, 0}, {zone_end, h, h});
  }
  // Pulse entirely inside the MPM zone: tail 3.5 mm past the interface, front 11.5 mm before
  // the far one. What is left in the FE part is the reflection.
  const double t_inside = (zone_start + pulse_length + 0.0035) / c;
  while (solver.time() < t_inside)
    solver.advance();
  advance_reference_to(solver.time());
  const double incident = reference.diagnostics().external_work;
  WaveResult r;
  // Energy the face pulse put into the pure-FE bar (analytic: 3/8 rho c A v0^2 T).
  r.incident_over_analytic =
    incident / (0.375 * 1000.0 * c * h * h * pulse_velocity * pulse_velocity * duration);
  const fem::FeDiagnostics d = solver.fe().diagnostics();
  const double reflected = d.kinetic_energy + d.strain_energy;
  const auto m = solver.mpm().diagnostics();
  const double transmitted = m.kinetic_energy + m.strain_energy;
  r.reflected_ratio = reflected / (reflected + transmitted);
  r.energy_ratio = (reflected + transmitted) / incident;
  r.conversions = solver.conversions().size();

  // Transmitted pulse in the far FE part against the pure-FE bar at the same time.
  const double t_out = (zone_end + pulse_length + 0.007) / c;
  while (solver.time() < t_out)
    solver.advance();
  advance_reference_to(solver.time());
  const auto hybrid_v = right_part_velocities(solver.fe());
  const auto reference_v = right_part_velocities(reference);
  r.hybrid_nodes = hybrid_v.size();
  r.reference_nodes = reference_v.size();
  double difference = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < std::min(hybrid_v.size(), reference_v.size()); ++i)
  {
    difference += std::pow(hybrid_v[i].second - reference_v[i].second, 2);
    norm += std::pow(reference_v[i].second, 2);
  }
  r.transmitted_error = norm > 0.0 ? std::sqrt(difference / norm) : INFINITY;
  r.books = books_of(solver, incident, 1000.0 * h * h * pulse_length * pulse_velocity);
  r.transits_per_window = windows.substeps * windows.mpm_cfl;
  r.windows_per_pulse = windows.substeps > 0 ? duration / (windows.substeps * windows.mpm_cfl * h / c) : 0.0;
  r.books.seconds = seconds_since(start);
  return r;
}
} // namespace vulnus::verification
