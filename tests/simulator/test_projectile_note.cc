// The closing note that points to the rigid model when an elastic projectile's own substeps
// take most of a run (the paper's 50 m/s scenes), and stays silent otherwise.
#include "simulator/mpm_stepper.h"

#include <gtest/gtest.h>

using vulnus::simulator::elastic_projectile_note;

TEST(ElasticProjectileNote, NamesTheRigidModelWhenTheSubstepsDominate)
{
  // The coarse isotropic 50 m/s run: 57 of 74 s in the substeps, peak von Mises 0.04 of yield.
  const std::string note = elastic_projectile_note(57.0, 74.0, 0.04, "bullet");
  EXPECT_NE(note.find("'Material bullet/Model = rigid'"), std::string::npos) << note;
  EXPECT_NE(note.find("77 %"), std::string::npos) << note;
  EXPECT_NE(note.find("0.04 of its yield"), std::string::npos) << note;
}

TEST(ElasticProjectileNote, SilentWhenTheProjectileYieldsOrTheSubstepsAreCheap)
{
  EXPECT_EQ(elastic_projectile_note(57.0, 74.0, 0.25, "bullet"), ""); // 150 m/s: it deforms
  EXPECT_EQ(elastic_projectile_note(30.0, 74.0, 0.04, "bullet"), ""); // under half the run
  EXPECT_EQ(elastic_projectile_note(0.0, 0.0, 0.0, "bullet"), "");    // nothing ran
}

// The closing line that names an unresolved penetration depth: only for a projectile that
// stopped in the target, from summary.json's penetration.resolution.
TEST(UnresolvedPenetrationReport, NamesTheDepthOfAStoppedProjectileBelowTheCellsNeeded)
{
  using vulnus::simulator::unresolved_penetration_report;
  nlohmann::json summary = {
    {"penetration",
     {{"stopped", true},
      {"resolution", {{"resolved", false}, {"reason", "the projectile spans 8.8 cells across"}}}}}};
  const std::string line = unresolved_penetration_report(summary);
  EXPECT_NE(line.find("penetration depth not resolved"), std::string::npos) << line;
  EXPECT_NE(line.find("8.8 cells across"), std::string::npos) << line;

  summary["penetration"]["stopped"] = false; // perforated, or still moving: no depth to judge
  EXPECT_EQ(unresolved_penetration_report(summary), "");
  summary["penetration"]["stopped"] = true;
  summary["penetration"]["resolution"]["resolved"] = true;
  EXPECT_EQ(unresolved_penetration_report(summary), "");
  EXPECT_EQ(unresolved_penetration_report(nlohmann::json::object()), ""); // no projectile
}
