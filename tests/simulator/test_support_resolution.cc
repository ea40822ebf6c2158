// The supports' resolution rule of a hybrid run: a supported face whose far-field cells are
// wider across it than the bound in grid cells is flagged, by name, with the remedy; free faces and
// faces the far field does not reach are not.
#include "simulator/support_resolution.h"

#include <gtest/gtest.h>

using namespace vulnus::simulator;

TEST(SupportResolution, FlagsSupportedFacesWithCellsBeyondTheBound)
{
  const double h = 1e-3;
  // x- and x+ 2.54 mm (the default grading of a 6 mm far field), y faces free at 4 mm, z- at
  // the bound exactly, z+ not reached by the far field.
  const std::array<double, 6> cells = {{2.54e-3, 2.54e-3, 4e-3, 4e-3, 2e-3, 0.0}};
  const std::array<bool, 6> supported = {{true, true, false, false, true, true}};
  const std::array<FaceResolution, 6> r = support_resolution(cells, supported, h);
  EXPECT_FALSE(r[0].resolved);
  EXPECT_NEAR(r[0].over_grid_cell, 2.54, 1e-12);
  EXPECT_FALSE(r[1].resolved);
  EXPECT_TRUE(r[2].resolved);
  EXPECT_FALSE(r[2].supported);
  EXPECT_TRUE(r[4].resolved);
  EXPECT_TRUE(r[5].resolved);
  EXPECT_FALSE(r[5].supported);
  const std::vector<std::string> warnings = support_resolution_warnings(r, h);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("x- (2.54 grid cells), x+ (2.54 grid cells)"), std::string::npos)
    << warnings[0];
  EXPECT_EQ(warnings[0].find("z-"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("Far field/Supported face cells <= 2"), std::string::npos)
    << warnings[0];
}

TEST(SupportResolution, SilentWhenEverySupportedFaceIsFineEnough)
{
  const std::array<double, 6> cells = {{1e-3, 1e-3, 4e-3, 4e-3, 1.5e-3, 1.5e-3}};
  const std::array<bool, 6> supported = {{true, true, false, false, true, true}};
  EXPECT_TRUE(support_resolution_warnings(support_resolution(cells, supported, 1e-3), 1e-3).empty());
}
