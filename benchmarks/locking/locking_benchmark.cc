// Volumetric locking and its cure in MPM and in the far field: the period of the
// divergence-free shear mode (shear_mode.h) against its analytic value, at bulk:shear 1e2, 1e4
// and 1e6, on 10 and 20 cells per side, with each point's own J and with the cell's.
// Usage: locking_benchmark [--ratios 1e2,1e4,1e6] [--quick] (quick: 1e4 only)
#include "benchmarks/locking/shear_mode.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace vulnus;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<double> ratios = {1e2, 1e4, 1e6};
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--quick") == 0)
      ratios = {1e4};
    else if (std::strcmp(argv[i], "--ratios") == 0 && i + 1 < argc)
    {
      ratios.clear();
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');)
        ratios.push_back(std::stod(item));
    }
  std::printf("%-9s %-8s %-6s %5s %12s %12s %9s %9s\n", "method", "K/mu", "J", "cells",
              "T/T_exact", "error", "steps", "seconds");
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
  return 0;
}
