// The resolution rule of the wound figures (analysis/wound_resolution.h) on hand-built metrics:
// a wound narrower than the cells needed is flagged, the same wound at a finer cell is not,
// and in a fibred target only the matrix-failed volume is ever resolved.
#include "analysis/wound_resolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace vulnus::analysis;

namespace
{
/// A tract of circular debris and total failure, diameter d, 10 mm long, with round face
/// wounds and outlines of that diameter.
WoundMetrics round_wound(const double d)
{
  WoundMetrics m;
  m.path = path_through_box(Vector3(-20e-3, 0, -20e-3), Vector3(20e-3, 10e-3, 20e-3),
                            Vector3(0, -5e-3, 0), Vector3::UnitY());
  const double area = M_PI * d * d / 4.0;
  m.tract_area.assign(10, area);
  m.debris_tract_area.assign(10, area);
  m.volumes[3] = area * 10e-3;
  m.debris_volume = m.volumes[3];
  for (FaceWound* w : {&m.entrance, &m.exit})
  {
    w->face = w == &m.entrance ? 2 : 3;
    w->n_points = 100;
    w->equivalent_diameter = d;
    w->outline.measured = true;
    w->outline.equivalent_diameter = d;
    w->outline.aspect_ratio = 4.0; // its narrowest width is d / 2
  }
  return m;
}

std::map<std::string, FigureResolution> by_name(const std::vector<FigureResolution>& list)
{
  std::map<std::string, FigureResolution> out;
  for (const FigureResolution& r : list)
    out[r.figure] = r;
  return out;
}
} // namespace

TEST(WoundResolution, AWoundNarrowerThanTheCellsNeededIsFlaggedAndAFinerCellResolvesIt)
{
  const WoundMetrics m = round_wound(10e-3);
  const auto coarse = by_name(resolve_wound_figures(m, 1e-3, false));   // 10 cells across
  const auto fine = by_name(resolve_wound_figures(m, 0.5e-3, false));   // 20 cells across
  EXPECT_NEAR(coarse.at("debris").cells_across, 10.0, 1e-9);
  EXPECT_FALSE(coarse.at("debris").resolved);
  EXPECT_FALSE(coarse.at("failed_volume_m3.total").resolved);
  EXPECT_TRUE(fine.at("debris").resolved);
  EXPECT_TRUE(fine.at("tract.area_m2").resolved);
  EXPECT_TRUE(fine.at("entrance_wound").resolved);
  // The outline's narrowest width is half its diameter: 10 cells at 0.5 mm.
  EXPECT_NEAR(fine.at("exit_wound.outline").cells_across, 10.0, 1e-9);
  EXPECT_FALSE(fine.at("exit_wound.outline").resolved);
  EXPECT_TRUE(by_name(resolve_wound_figures(m, 0.25e-3, false)).at("exit_wound.outline").resolved);
}

TEST(WoundResolution, InAFibredTargetOnlyTheMatrixFailedVolumeIsResolved)
{
  const WoundMetrics m = round_wound(12e-3);
  const auto fine = by_name(resolve_wound_figures(m, 0.1e-3, true)); // 120 cells across
  for (const char* figure : {"failed_volume_m3.total", "tract.area_m2", "entrance_wound",
                             "exit_wound", "debris", "tract.debris_area_m2",
                             "entrance_wound.outline", "exit_wound.outline"})
  {
    EXPECT_FALSE(fine.at(figure).resolved) << figure;
    EXPECT_FALSE(fine.at(figure).reason.empty()) << figure;
  }
  EXPECT_NE(fine.at("debris").reason, fine.at("failed_volume_m3.total").reason);
  EXPECT_TRUE(fine.at("failed_volume_m3.matrix").resolved);
  EXPECT_FALSE(by_name(resolve_wound_figures(m, 1.1e-3, true)).at("failed_volume_m3.matrix").resolved);
  EXPECT_EQ(fine.count("failed_volume_m3.fiber"), 0u); // no fibre-failed point: no figure
  // The same wound in an isotropic target: every figure resolved at this cell.
  for (const FigureResolution& r : resolve_wound_figures(m, 0.1e-3, false))
    EXPECT_TRUE(r.resolved) << r.figure;
}

TEST(WoundResolution, AnEmptyRegionHasNoFigureToJudge)
{
  WoundMetrics none;
  EXPECT_TRUE(resolve_wound_figures(none, 1e-3, true).empty());
}
