// MPM throughput of a deck (default: the coarse anisotropic 150 m/s paper scene): particle-
// steps per second and seconds per phase, for 1 and 2 threads and linear, GIMP and CPDI shape
// functions, and resident memory per particle. All configurations in one run, so the ratios
// compare like with like on a shared machine.
#include "deck/deck_reader.h"
#include "mpm/solver.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace vulnus;

/// A line "Key:   N kB" of /proc/self/status, in bytes (0 when absent).
double proc_status_bytes(const std::string& key)
{
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.compare(0, key.size() + 1, key + ":") == 0)
    {
      std::istringstream fields(line.substr(key.size() + 1));
      double kilobytes = 0.0;
      fields >> kilobytes;
      return 1024.0 * kilobytes;
    }
  return 0.0;
}

struct Measurement
{
  double point_steps_per_second = 0.0;
  mpm::PhaseTimes phases; ///< seconds over the measured steps
  double seconds = 0.0;
  std::size_t points = 0, steps = 0;
  double resident_bytes_per_point = 0.0;
  std::size_t active_nodes = 0, box_nodes = 0, contact_nodes = 0, seam_nodes = 0;
  double time_step = 0.0;
};

mpm::PhaseTimes difference(const mpm::PhaseTimes& after, const mpm::PhaseTimes& before)
{
  mpm::PhaseTimes d;
  d.time_step = after.time_step - before.time_step;
  d.particle_to_grid = after.particle_to_grid - before.particle_to_grid;
  d.grid_update = after.grid_update - before.grid_update;
  d.contact = after.contact - before.contact;
  d.grid_to_particle = after.grid_to_particle - before.grid_to_particle;
  d.nonlocal_failure = after.nonlocal_failure - before.nonlocal_failure;
  d.stress_update = after.stress_update - before.stress_update;
  d.projectile_substeps = after.projectile_substeps - before.projectile_substeps;
  d.checks_and_sorting = after.checks_and_sorting - before.checks_and_sorting;
  d.coupling = after.coupling - before.coupling;
  return d;
}

Measurement measure(mpm::SceneParameters scene, const int threads, const mpm::ShapeFunction shape,
                    const std::size_t warmup, const std::size_t steps)
{
  scene.shape_function = shape;
  scene.end_time = 1.0; // never the limit here
  scene.n_threads = static_cast<unsigned int>(threads);
  omp_set_num_threads(threads);
  const double resident_before = proc_status_bytes("VmRSS");
  auto solver = std::make_unique<mpm::Solver>(scene);
  for (std::size_t s = 0; s < warmup; ++s)
    solver->advance();
  Measurement m;
  m.points = solver->points().size();
  m.resident_bytes_per_point = (proc_status_bytes("VmRSS") - resident_before) / m.points;
  const mpm::PhaseTimes before = solver->phase_times();
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t s = 0; s < steps && !solver->finished(); ++s, ++m.steps)
    solver->advance();
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.phases = difference(solver->phase_times(), before);
  m.point_steps_per_second = double(m.points) * m.steps / m.seconds;
  m.active_nodes = solver->active_nodes();
  m.time_step = solver->last_time_step();
  m.box_nodes = solver->background_grid().n_box_nodes();
  m.seam_nodes = solver->background_grid().n_contested();
  m.contact_nodes = solver->contact_nodes();
  return m;
}

/// Memory per point is meaningful only for the first configuration: later ones reuse what
/// the earlier ones freed.
void print_row(const char* label, const Measurement& m, const bool first)
{
  const mpm::PhaseTimes& p = m.phases;
  const double per = 1e9 / (double(m.points) * m.steps); // ns per point-step
  std::printf("%-16s %8.2f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8s\n", label,
              m.point_steps_per_second / 1e6, per * p.particle_to_grid, per * p.grid_update,
              per * p.contact, per * p.grid_to_particle,
              per * (p.nonlocal_failure + p.stress_update + p.projectile_substeps),
              per * (p.time_step + p.checks_and_sorting), per * p.total(),
              first ? std::to_string(int(m.resident_bytes_per_point)).c_str() : "-");
}
/// The same scene with one material change, linear, 2 threads.
Measurement measure_variant(mpm::SceneParameters scene,
                            const std::function<void(mpm::SceneParameters&)>& change,
                            const std::size_t warmup, const std::size_t steps)
{
  change(scene);
  return measure(scene, 2, mpm::ShapeFunction::linear, warmup, steps);
}

/// The stress column includes the nonlocal failure criterion and a subcycled projectile's
/// substeps (its own stress updates).
double stress_ns(const Measurement& m)
{
  return 1e9 * (m.phases.nonlocal_failure + m.phases.stress_update + m.phases.projectile_substeps) /
         (double(m.points) * m.steps);
}

/// 2 threads / 1 thread from `repeats` further pairs measured back to back (1 then 2 threads),
/// so that a slow spell of the shared machine spoils one pair, not the figure: every pair's
/// ratio and their median.
void report_thread_scaling(const mpm::SceneParameters& scene, const std::size_t warmup,
                           const std::size_t steps, const std::size_t repeats)
{
  if (repeats == 0)
    return;
  for (const mpm::ShapeFunction shape : {mpm::ShapeFunction::linear, mpm::ShapeFunction::gimp})
  {
    std::vector<double> ratios;
    for (std::size_t r = 0; r < repeats; ++r)
    {
      const double one = measure(scene, 1, shape, warmup, steps).point_steps_per_second;
      const double two = measure(scene, 2, shape, warmup, steps).point_steps_per_second;
      ratios.push_back(two / one);
    }
    std::printf("  %s, %zu pairs 1 then 2 threads:", mpm::shape_function_name(shape),
                repeats);
    for (const double ratio : ratios)
      std::printf(" %.2f", ratio);
    std::sort(ratios.begin(), ratios.end());
    std::printf("; median %.2f\n", ratios[ratios.size() / 2]);
  }
}

/// Seconds of `repeats` passes of f on `threads` threads (best of three).
template <class F>
double best_time(const int threads, const int repeats, F&& f)
{
  double best = 1e300;
  for (int trial = 0; trial < 3; ++trial)
  {
    const double start = omp_get_wtime();
    for (int r = 0; r < repeats; ++r)
      f(threads);
    best = std::min(best, omp_get_wtime() - start);
  }
  return best;
}

/// What this machine allows two threads at best, measured now: a memory-bound triad over
/// arrays far larger than the caches, and a loop of pure arithmetic. The MPM ratios are to be
/// read against these.
void report_machine_ceiling()
{
  const long n = 8L << 20; // 3 x 64 MB
  std::vector<double> a(n, 1.0), b(n, 2.0), c(n, 0.0);
  const auto triad = [&](const int threads) {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (long i = 0; i < n; ++i)
      c[i] = a[i] + 1.0001 * b[i];
  };
  volatile double sink = 0.0; // keeps the arithmetic loop from being optimized away
  const auto arithmetic = [&](const int threads) {
    double sum = 0.0;
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : sum)
    for (long i = 0; i < 50'000'000L; ++i)
    {
      const double x = 1e-8 * double(i);
      sum += std::sqrt(x + 1.0) * x;
    }
    sink = sink + sum;
  };
  const double triad_one = best_time(1, 10, triad), triad_two = best_time(2, 10, triad);
  const double arithmetic_one = best_time(1, 1, arithmetic),
               arithmetic_two = best_time(2, 1, arithmetic);
  std::printf("machine ceiling, same run: 2 threads / 1 thread %.2f for a memory-bound triad "
              "(%.1f GB/s on 1 thread), %.2f for pure arithmetic\n",
              triad_one / triad_two, 10 * 3 * 8.0 * n / triad_one / 1e9,
              arithmetic_one / arithmetic_two);
}

/// What each skip saves, measured on variants of the scene.
void report_skips(const mpm::SceneParameters& scene, const Measurement& base,
                  const std::size_t warmup, const std::size_t steps)
{
  const bool tissue = std::any_of(scene.materials.begin(), scene.materials.end(),
                                  [](const mpm::NamedMaterial& m)
                                  { return m.parameters.model == "transversely isotropic hyperelastic"; });
  std::printf("\nskips (linear, 2 threads; stress = ns per point-step of the stress phase)\n");
  const double per = 1e9 / (double(base.points) * base.steps);
  std::printf("  sparse grid: %zu active of %zu box nodes (%.1f %%): node loops do %.1f %% of a "
              "dense grid's work\n",
              base.active_nodes, base.box_nodes, 100.0 * base.active_nodes / base.box_nodes,
              100.0 * base.active_nodes / base.box_nodes);
  std::printf("  thread-private node fields: none; %zu seam nodes of %zu active (%.1f %%) touched by "
              "two threads' points go through per-thread buffers\n",
              base.seam_nodes, base.active_nodes, 100.0 * base.seam_nodes / base.active_nodes);
  std::printf("  contact pass: %.1f ns/point-step (%.1f %% of the step) at %zu nodes where bodies "
              "meet; skipped entirely with one body or contact off\n",
              per * base.phases.contact, 100.0 * base.phases.contact / base.phases.total(),
              base.contact_nodes);
  if (tissue)
  {
    auto each_tissue = [](const std::function<void(materials::TissueParameters&)>& f)
    {
      return [f](mpm::SceneParameters& s)
      {
        for (mpm::NamedMaterial& m : s.materials)
          if (m.parameters.model == "transversely isotropic hyperelastic")
            f(m.parameters.tissue);
      };
    };
    const Measurement isotropic = measure_variant(
        scene, each_tissue([](materials::TissueParameters& t) { t.with_fibers = false; }), warmup,
        steps);
    std::printf("  no fiber work (isotropic tissue): stress %.1f against %.1f anisotropic (%.2f x)\n",
                stress_ns(isotropic), stress_ns(base), stress_ns(isotropic) / stress_ns(base));
    const Measurement no_failure = measure_variant(
        scene, each_tissue([](materials::TissueParameters& t) { t.failure.enabled = false; }),
        warmup, steps);
    std::printf("  no eigenvalues (failure off): stress %.1f against %.1f with failure (%.2f x)\n",
                stress_ns(no_failure), stress_ns(base), stress_ns(no_failure) / stress_ns(base));
  }
  int projectile = -1;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (scene.bodies[b].is_projectile)
      projectile = static_cast<int>(b);
  if (projectile >= 0)
  {
    const std::string name = scene.bodies[projectile].material;
    const Measurement rigid = measure_variant(
        scene,
        [&](mpm::SceneParameters& s)
        {
          for (mpm::NamedMaterial& m : s.materials)
            if (m.name == name)
              m.parameters.model = "rigid";
        },
        warmup, steps);
    std::printf("  rigid projectile (no stress update for its points): stress %.1f against %.1f "
                "(%.2f x); time step %.3g s against %.3g s (%.1f x larger)\n",
                stress_ns(rigid), stress_ns(base), stress_ns(rigid) / stress_ns(base),
                rigid.time_step, base.time_step, rigid.time_step / base.time_step);
  }
}
} // namespace

int main(int argc, char** argv)
{
  const std::string source = VULNUS_SOURCE_DIR;
  std::string deck = source + "/inputs/paper/anisotropic_150ms_coarse.prm";
  std::size_t steps = 40, warmup = 20, repeats = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string argument = argv[i];
    if (argument == "--steps" && i + 1 < argc)
      steps = std::stoul(argv[++i]);
    else if (argument == "--warmup" && i + 1 < argc)
      warmup = std::stoul(argv[++i]);
    else if (argument == "--repeats" && i + 1 < argc)
      repeats = std::stoul(argv[++i]);
    else if (argument.rfind("--", 0) != 0)
      deck = argument;
    else
    {
      std::cerr << "usage: throughput [DECK] [--steps N] [--warmup N] [--repeats N]\n";
      return 2;
    }
  }
  deck::RunParameters parameters;
  try
  {
    parameters = deck::read_run_parameters(deck);
  }
  catch (const deck::DeckError& error)
  {
    for (const std::string& message : error.messages())
      std::cerr << "throughput: " << message << '\n';
    return 2;
  }

  std::printf("deck %s: %zu warm-up steps, then %zu measured steps per configuration\n",
              deck.c_str(), warmup, steps);
  std::printf("%-16s %8s %8s %8s %8s %8s %8s %8s %8s %8s\n", "configuration", "Mpt-st/s", "P2G",
              "grid", "contact", "G2P", "stress", "other", "total", "B/point");
  std::printf("%-16s %8s %8s %8s %8s %8s %8s %8s %8s %8s\n", "", "", "ns/pt-st", "", "", "", "",
              "", "", "(RSS)");
  Measurement linear[2], gimp[2], cpdi[2];
  for (int t = 1; t <= 2; ++t)
  {
    linear[t - 1] = measure(parameters.scene, t, mpm::ShapeFunction::linear, warmup, steps);
    print_row(t == 1 ? "linear, 1 thr" : "linear, 2 thr", linear[t - 1], t == 1);
    gimp[t - 1] = measure(parameters.scene, t, mpm::ShapeFunction::gimp, warmup, steps);
    print_row(t == 1 ? "GIMP, 1 thr" : "GIMP, 2 thr", gimp[t - 1], false);
    cpdi[t - 1] = measure(parameters.scene, t, mpm::ShapeFunction::cpdi, warmup, steps);
    print_row(t == 1 ? "CPDI, 1 thr" : "CPDI, 2 thr", cpdi[t - 1], false);
  }
  std::printf("points %zu\n", linear[0].points);
  std::printf("2 threads / 1 thread: linear %.2f, GIMP %.2f, CPDI %.2f\n",
              linear[1].point_steps_per_second / linear[0].point_steps_per_second,
              gimp[1].point_steps_per_second / gimp[0].point_steps_per_second,
              cpdi[1].point_steps_per_second / cpdi[0].point_steps_per_second);
  report_thread_scaling(parameters.scene, warmup, steps, repeats);
  std::printf("GIMP / linear (2 threads): %.2f, CPDI / linear: %.2f\n",
              gimp[1].point_steps_per_second / linear[1].point_steps_per_second,
              cpdi[1].point_steps_per_second / linear[1].point_steps_per_second);
  std::printf("resident memory of the first scene: %.0f B/point (growth of the resident set over "
              "building it and its warm-up steps)\n",
              linear[0].resident_bytes_per_point);
  std::printf("peak resident set of the process %.0f MB (libraries included)\n",
              proc_status_bytes("VmHWM") / 1e6);
  report_machine_ceiling(); // after the peak: its arrays would count in it
  report_skips(parameters.scene, linear[1], warmup, steps);
  return 0;
}
