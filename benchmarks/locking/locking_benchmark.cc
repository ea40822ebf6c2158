// Volumetric locking and its cure in MPM and in the far field: the period and the pressure
// of the roller square's eigenmodes (square_modes.h; shear: divergence-free, no pressure;
// dilatation: the pressure wave) against their analytic values, at bulk:shear 1e2, 1e4 and
// 1e6, with each point's own J, the cell's, and (MPM) the cell's grid flux; then the far
// field's thick cylinder (lame_cylinder.h) against Lame's solution under refinement: the
// errors of displacement, pressure and stresses with the observed order of each halving.
// Usage: locking_benchmark [--ratios 1e2,1e4,1e6] [--quick] (quick: 1e4 only)
//                          [--only modes|lame] [--modes shear,dilatation] [--cells 10,20]
//                          [--strain 1e-4] [--transfer flip|apic|relaxed-apic] (MPM's)
#include "benchmarks/locking/lame_cylinder.h"
#include "benchmarks/locking/square_modes.h"

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace vulnus;

namespace
{
/// log2 of an error's ratio between two successive halvings of the cell, as text; empty on
/// the first grid or where an error is nil.
std::string observed_order(const bool refined, const double coarse, const double fine)
{
  char text[16] = "";
  if (refined && coarse > 0 && fine > 0)
    std::snprintf(text, sizeof text, "%.2f", std::log2(coarse / fine));
  return text;
}

struct TransferName
{
  const char* option;
  const char* label;
  mpm::VelocityTransfer transfer;
};
const TransferName transfer_names[] = {{"flip", "FLIP", mpm::VelocityTransfer::flip},
                                       {"apic", "APIC", mpm::VelocityTransfer::apic},
                                       {"relaxed-apic", "relaxed APIC",
                                        mpm::VelocityTransfer::relaxed_apic}};

const char* mode_name(const verification::SquareMode mode)
{
  return mode == verification::SquareMode::shear ? "shear" : "dilatation";
}

std::vector<std::string> split(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');)
    items.push_back(item);
  return items;
}

/// Each method on each grid in turn; the order of an error is log2 of its ratio between
/// successive halvings of the cell.
void square_mode_table(const std::vector<double>& ratios,
                       const std::vector<verification::SquareMode>& modes,
                       const std::vector<unsigned>& cell_counts, const double strain,
                       const mpm::VelocityTransfer transfer)
{
  using verification::SquareMode;
  using verification::SquareModeResult;
  const char* transfer_name = "";
  for (const TransferName& t : transfer_names)
    if (t.transfer == transfer)
      transfer_name = t.label;
  std::printf("Square modes at strain %g (MPM velocity transfer %s): the period and the "
              "pressure at T/4 against the analytic ones\n",
              strain, transfer_name);
  std::printf("p error: cells' mean pressure against the exact one at their centres (rms, and "
              "p mean: its signed mean); point p (MPM): each point's\n");
  std::printf("%-9s %-10s %-8s %-5s %5s %10s %10s %6s %10s %6s %10s %10s %6s %8s %8s\n",
              "method", "mode", "K/mu", "J", "cells", "T/T_exact", "T error", "order", "p error",
              "order", "p mean", "point p", "order", "steps", "seconds");
  using Run = std::function<SquareModeResult(SquareMode, unsigned, double)>;
  struct Variant
  {
    const char* method;
    const char* volume; ///< own J, the cell's J, or (MPM) the cell's grid flux
    Run run;
  };
  std::vector<Variant> variants;
  auto add_fe = [&](const char* method, fem::TimeIntegrator integrator, bool one_point)
  {
    for (const bool averaging : {false, true})
      variants.push_back({method, averaging ? "cell" : "own",
                          [=](SquareMode mode, unsigned cells, double ratio) {
                            return verification::fe_square_mode(mode, cells, ratio, averaging,
                                                                integrator, one_point, strain);
                          }});
  };
  add_fe("FE expl", fem::TimeIntegrator::central_difference, false);
  add_fe("FE 1pt", fem::TimeIntegrator::central_difference, true);
  add_fe("FE Newm", fem::TimeIntegrator::newmark, false);
  using verification::PointVolume;
  const std::pair<const char*, PointVolume> point_volumes[] = {
      {"own", PointVolume::own}, {"cell", PointVolume::cell}, {"flux", PointVolume::grid_flux}};
  for (const auto& [label, volume] : point_volumes)
    variants.push_back({"MPM", label,
                        [=, volume = volume](SquareMode mode, unsigned cells, double ratio) {
                          return verification::mpm_square_mode(mode, cells, ratio, volume,
                                                               strain, transfer);
                        }});
  for (const double ratio : ratios)
    for (const SquareMode mode : modes)
      for (const Variant& variant : variants)
      {
        SquareModeResult previous;
        for (const unsigned cells : cell_counts)
        {
          const SquareModeResult r = variant.run(mode, cells, ratio);
          const double error = std::abs(r.period_ratio - 1.0);
          const bool refined = previous.steps > 0;
          auto order_of = [&](double coarse, double fine)
          { return observed_order(refined, coarse, fine); };
          char point_pressure[16] = "-";
          if (r.point_pressure_error > 0)
            std::snprintf(point_pressure, sizeof point_pressure, "%.2e", r.point_pressure_error);
          std::printf(
              "%-9s %-10s %-8.0e %-5s %5u %10.5f %10.2e %6s %10.2e %6s %10.2e %10s %6s %8lu "
              "%8.2f\n",
              variant.method, mode_name(mode), ratio, variant.volume, cells, r.period_ratio, error,
              order_of(std::abs(previous.period_ratio - 1.0), error).c_str(), r.pressure_error,
              order_of(previous.pressure_error, r.pressure_error).c_str(),
              r.mean_pressure_error, point_pressure,
              order_of(previous.point_pressure_error, r.point_pressure_error).c_str(), r.steps,
              r.seconds);
          std::fflush(stdout);
          previous = r;
        }
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
        { return observed_order(cells > 4, previous.*error, r.*error); };
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
  using verification::SquareMode;
  std::vector<double> ratios = {1e2, 1e4, 1e6};
  std::vector<SquareMode> modes = {SquareMode::shear, SquareMode::dilatation};
  std::vector<unsigned> cells = {10, 20};
  double strain = 1e-4;
  mpm::VelocityTransfer transfer = mpm::VelocityTransfer::flip;
  bool square = true, lame = true, quick = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    const bool has_value = i + 1 < argc;
    if (option == "--quick")
    {
      ratios = {1e4};
      quick = true;
    }
    else if (option == "--only" && has_value)
    {
      const std::string which = argv[++i];
      square = which == "modes";
      lame = which == "lame";
    }
    else if (option == "--ratios" && has_value)
    {
      ratios.clear();
      for (const std::string& item : split(argv[++i]))
        ratios.push_back(std::stod(item));
    }
    else if (option == "--modes" && has_value)
    {
      modes.clear();
      for (const std::string& item : split(argv[++i]))
      {
        for (const SquareMode known : {SquareMode::shear, SquareMode::dilatation})
          if (item == mode_name(known))
            modes.push_back(known);
        if (modes.empty() || item != mode_name(modes.back()))
        {
          std::fprintf(stderr, "locking_benchmark: --modes takes shear and dilatation, not %s\n",
                       item.c_str());
          return 2;
        }
      }
    }
    else if (option == "--cells" && has_value)
    {
      cells.clear();
      for (const std::string& item : split(argv[++i]))
        cells.push_back(static_cast<unsigned>(std::stoul(item)));
    }
    else if (option == "--strain" && has_value)
      strain = std::stod(argv[++i]);
    else if (option == "--transfer" && has_value)
    {
      const std::string name = argv[++i];
      const TransferName* found = nullptr;
      for (const TransferName& t : transfer_names)
        if (name == t.option)
          found = &t;
      if (found)
        transfer = found->transfer;
      else
      {
        std::fprintf(stderr,
                     "locking_benchmark: --transfer takes flip, apic or relaxed-apic, not %s\n",
                     name.c_str());
        return 2;
      }
    }
    else
    {
      std::fprintf(stderr, "locking_benchmark: unknown option or missing value: %s\n", argv[i]);
      return 2;
    }
  }
  if (square)
    square_mode_table(ratios, modes, cells, strain, transfer);
  if (lame)
    lame_table(ratios, quick);
  return 0;
}
