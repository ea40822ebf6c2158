// The resolution rule of a penetration depth (analysis/penetration_resolution.h): the
// projectile's width across its flight in cells against the cells needed.
#include "analysis/penetration_resolution.h"

#include <gtest/gtest.h>

using namespace vulnus::analysis;
using vulnus::scene::BodyParameters;
using vulnus::scene::BodyShape;
using vulnus::scene::Vector3;

namespace
{
BodyParameters bb()
{
  BodyParameters b;
  b.shape = BodyShape::sphere;
  b.radius = 2.2e-3;
  b.initial_velocity = Vector3(0, 180, 0);
  return b;
}
} // namespace

TEST(PenetrationResolution, TheFbiDecksBbIsNotResolvedAtItsCellAndIsAtTwentyCellsAcross)
{
  const PenetrationResolution deck = resolve_penetration(bb(), 0.5e-3);
  EXPECT_NEAR(deck.width_m, 4.4e-3, 1e-15);
  EXPECT_NEAR(deck.cells_across, 8.8, 1e-12);
  EXPECT_FALSE(deck.resolved);
  EXPECT_NE(deck.reason.find("8.8 cells across"), std::string::npos) << deck.reason;

  const PenetrationResolution fine = resolve_penetration(bb(), 0.22e-3);
  EXPECT_NEAR(fine.cells_across, 20.0, 1e-9);
  EXPECT_TRUE(fine.resolved);
  EXPECT_TRUE(fine.reason.empty());
}

TEST(PenetrationResolution, ACylinderIsMeasuredByItsDiameterABoxAcrossItsFlight)
{
  BodyParameters bullet = bb();
  bullet.shape = BodyShape::cylinder;
  bullet.radius = 4.5e-3;
  bullet.length = 15e-3;
  EXPECT_NEAR(projectile_width(bullet), 9e-3, 1e-15);

  // A plate 2 x 30 x 10 mm flying along y: its narrowest extent across y is 2 mm, not the
  // 30 mm along its flight.
  BodyParameters plate;
  plate.shape = BodyShape::box;
  plate.box_min = Vector3(0, 0, 0);
  plate.box_max = Vector3(2e-3, 30e-3, 10e-3);
  plate.initial_velocity = Vector3(0, -50, 0);
  EXPECT_NEAR(projectile_width(plate), 2e-3, 1e-15);
  // Flying along x, the narrowest extent across x is 10 mm.
  plate.initial_velocity = Vector3(50, 0, 0);
  EXPECT_NEAR(projectile_width(plate), 10e-3, 1e-15);
  EXPECT_FALSE(resolve_penetration(plate, 1e-3).resolved);
  EXPECT_TRUE(resolve_penetration(plate, 0.5e-3).resolved);
}
