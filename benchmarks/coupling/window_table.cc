// Implicit far-field windows against their length: the struck block and the plane wave
// (window_runs.h) with Newmark windows of about 1, 10, 50 and 200 wave transits of the
// interface cell, balanced (shortened to one transit) and with the dashpot, beside the
// explicit far field at its own step. Prints one row per run; asserts nothing.
// Usage: window_table [--block-only | --wave-only]   (about 7 minutes on 2 cores)
#include "benchmarks/coupling/window_runs.h"

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <cstring>

using namespace vulnus;
using verification::WindowSettings;

namespace
{
WindowSettings newmark(const unsigned int substeps, const double mpm_cfl, const bool dashpot)
{
  WindowSettings w;
  w.integrator = fem::TimeIntegrator::newmark;
  w.substeps = substeps;
  w.mpm_cfl = mpm_cfl;
  w.dashpot = dashpot;
  return w;
}

const char* kind(const WindowSettings& w)
{
  if (w.integrator == fem::TimeIntegrator::central_difference)
    return "explicit";
  return w.dashpot ? "dashpot" : "balanced";
}

void block_row(const WindowSettings& w, const double end_time)
{
  const verification::StruckBlockResult r = verification::run_struck_block(w, end_time);
  const verification::WindowBooks& b = r.books;
  std::printf("%-9s %5u %9.1f %7.1f %11.1e %11.1e %9.3f %9.3f %11.1e %6lu %5lu %6lu %7.1f %7.1f\n",
              kind(w), w.substeps, w.substeps > 0 ? r.transits_per_window : 0.0, end_time * 1e3,
              r.momentum_drift, b.created_momentum, r.energy_growth, r.energy_at_end,
              b.interface_energy_error, b.mpm_steps, b.fe_steps, b.windows_shortened,
              b.effective_mass_seconds, b.seconds);
  std::fflush(stdout);
}

void wave_row(const coupling::CouplingScheme scheme, const WindowSettings& w)
{
  const verification::WaveResult r = verification::run_wave_through_interface(scheme, w, false);
  const verification::WindowBooks& b = r.books;
  if (!(r.energy_ratio > 0.0))
  {
    // A Newmark step samples the face load at its ends: a window longer than the pulse can
    // step over all of it.
    std::printf("%-9s %5u %9.1f %9.2f   no energy entered: the window steps over the whole "
                "pulse (MPM %lu, FE %lu)\n",
                kind(w), w.substeps, r.transits_per_window, r.windows_per_pulse, b.mpm_steps,
                b.fe_steps);
    std::fflush(stdout);
    return;
  }
  std::printf("%-9s %5u %9.1f %9.2f %11.1e %9.3f %11.1e %11.1e %9.3f %6lu %5lu %6lu %7.1f\n",
              kind(w), w.substeps, w.substeps > 0 ? r.transits_per_window : 0.0,
              r.windows_per_pulse, r.reflected_ratio, r.energy_ratio, b.created_momentum,
              b.interface_energy_error, r.transmitted_error, b.mpm_steps, b.fe_steps,
              b.windows_shortened, b.seconds);
  std::fflush(stdout);
}
} // namespace

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool block = argc < 2 || std::strcmp(argv[1], "--wave-only") != 0;
  const bool wave = argc < 2 || std::strcmp(argv[1], "--block-only") != 0;
  if (block)
  {
    std::printf("struck block (12 mm free block, 4 mm zone, 0.3 m/s blow; Newmark windows of "
                "MPM steps of CFL 0.1; drift and created momentum over m v_max, energies over "
                "E0)\n");
    std::printf("%-9s %5s %9s %7s %11s %11s %9s %9s %11s %6s %5s %6s %7s %7s\n", "windows",
                "steps", "transits", "ms", "drift", "created", "growth", "at end",
                "interface", "MPM", "FE", "short", "M [s]", "wall");
    block_row(WindowSettings{fem::TimeIntegrator::central_difference, 0, 0.1, false}, 2e-3);
    block_row(newmark(10, 0.1, false), 2e-3);
    block_row(newmark(500, 0.1, false), 2e-3); // asked 50 transits, shortened to one
    block_row(newmark(10, 0.1, true), 4e-3);
    block_row(newmark(100, 0.1, true), 4e-3);
    block_row(newmark(500, 0.1, true), 8e-3);
    block_row(newmark(2000, 0.1, true), 15e-3);
  }
  if (wave)
  {
    std::printf("\nplane wave (pulse 20 cells long through a 30 mm MPM zone; Newmark windows of "
                "MPM steps of CFL 0.08; reflected and interface energy over the incident, "
                "created momentum over the pulse's m v, the transmitted pulse's L2 "
                "difference to the pure-FE bar)\n");
    std::printf("%-9s %5s %9s %9s %11s %9s %11s %11s %9s %6s %5s %6s %7s\n", "windows", "steps",
                "transits", "w/pulse", "reflected", "energy", "created", "interface",
                "pulse", "MPM", "FE", "short", "wall");
    const coupling::CouplingScheme multi = coupling::CouplingScheme::multi_step;
    wave_row(multi, WindowSettings{fem::TimeIntegrator::central_difference, 0, 0.08, false});
    wave_row(multi, newmark(10, 0.08, false));
    wave_row(multi, newmark(125, 0.08, false)); // asked 10 transits, shortened to one
    wave_row(multi, newmark(10, 0.08, true));
    wave_row(multi, newmark(125, 0.08, true));
    wave_row(multi, newmark(625, 0.08, true));
    wave_row(multi, newmark(2500, 0.08, true));
  }
  return 0;
}
