// Volumetric locking and its cure in MPM and in the far field: the period of the
// divergence-free shear mode (shear_mode.h) against its analytic value, at bulk:shear 1e2, 1e4
// and 1e6, on 10 and 20 cells per side, with each point's own J and with the cell's; then the
// far field's thick cylinder (lame_cylinder.h) against Lame's solution under refinement: the
// errors of displacement, pressure and stresses with the observed order of each halving.
// Usage: locking_benchmark [--ratios 1e2,1e4,1e6] [--quick] (quick: 1e4 only)
//                          [--only shear|lame]
#include "benchmarks/locking/lame_cylinder.h"
#include "benchmarks/locking/shear_mode.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace vulnus;

namespace
{
void shear_mode_table(const std::vector<double>& ratios)
{
  std::printf("Shear mode: the period against the analytic one\n");
  std::printf("%-9s %-8s %-6s %5s %12s %12s %9s %9s\n", "method", "K/mu", "J", "cells", "T/T_exact",
              "error", "steps", "seconds");
  auto row = [](const char* method, double ratio, bool averaging, unsigned cells,
                const verification::ShearModeResult& r)
  {
    std::printf("%-9s %-8.0e %-6s %5u %12.5f %12.2e %9lu %9.2f\n", method, ratio,
                averaging ? "cell" : "own", cells, r.period_ratio, std::abs(r.period_ratio - 1.0),
                r.steps, r.seconds);
    std::fflush(stdout);
  };
  for (const double ratio : ratios)
    for (const bool averaging : {false, true})
      for (const unsigned cells : {10u, 20u})
      {
        row("FE expl", ratio, averaging, cells,
            verification::fe_shear_mode(cells, ratio, averaging,
                                        fem::TimeIntegrator::central_difference));
        row("FE 1pt", ratio, averaging, cells,
            verification::fe_shear_mode(cells, ratio, averaging,
                                        fem::TimeIntegrator::central_difference, true));
        row("FE Newm", ratio, averaging, cells,
            verification::fe_shear_mode(cells, ratio, averaging, fem::TimeIntegrator::newmark));
        row("MPM", ratio, averaging, cells, verification::mpm_shear_mode(cells, ratio, averaging));
      }
}

/// Each variant on 4, 8, 16 (and 32) cells through the wall; the order of an error is
/// log2 of its ratio between successive halvings.
void lame_table(const std::vector<double>& ratios, const bool quick)
{
  std::printf(
      "\nLame cylinder (implicit far field, static): errors against the analytic solution\n");
  std::printf("%-9s %-8s %5s %7s %11s %6s %11s %6s %11s %6s %11s %11s %7s\n", "element", "K/mu",
              "cells", "n_cells", "u error", "order", "p error", "order", "s_rr error", "order",
              "s_tt error", "p/p_exact", "seconds");
  struct Variant
  {
    const char* name;
    bool averaging;
    unsigned int degree, finest;
  };
  const std::vector<Variant> variants = {{"Q1", false, 1, quick ? 16u : 32u},
                                         {"Q1 F-bar", true, 1, quick ? 16u : 32u},
                                         {"Q2", false, 2, quick ? 8u : 16u}};
  for (const double ratio : ratios)
    for (const Variant& v : variants)
    {
      verification::LameResult previous;
      for (unsigned cells = 4; cells <= v.finest; cells *= 2)
      {
        const verification::LameResult r =
            verification::lame_cylinder(cells, ratio, v.averaging, v.degree);
        auto order = [&](double verification::LameResult::*error)
        {
          char text[16] = "";
          if (cells > 4)
            std::snprintf(text, sizeof text, "%.2f", std::log2(previous.*error / r.*error));
          return std::string(text);
        };
        std::printf("%-9s %-8.0e %5u %7llu %11.3e %6s %11.3e %6s %11.3e %6s %11.3e %11.5f %7.2f\n",
                    v.name, ratio, cells, r.cells, r.displacement_error,
                    order(&verification::LameResult::displacement_error).c_str(), r.pressure_error,
                    order(&verification::LameResult::pressure_error).c_str(), r.radial_stress_error,
                    order(&verification::LameResult::radial_stress_error).c_str(),
                    r.hoop_stress_error, r.mean_pressure / r.exact_pressure, r.seconds);
        std::fflush(stdout);
        previous = r;
      }
    }
}
} // namespace

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<double> ratios = {1e2, 1e4, 1e6};
  bool shear = true, lame = true, quick = false;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--quick") == 0)
    {
      ratios = {1e4};
      quick = true;
    }
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
    {
      const std::string which = argv[++i];
      shear = which == "shear";
      lame = which == "lame";
    }
    else if (std::strcmp(argv[i], "--ratios") == 0 && i + 1 < argc)
    {
      ratios.clear();
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');)
        ratios.push_back(std::stod(item));
    }
  if (shear)
    shear_mode_table(ratios);
  if (lame)
    lame_table(ratios, quick);
  return 0;
}
