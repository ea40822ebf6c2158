// `vulnus compare` (analysis/compare_runs.h): a run against itself, against a perturbed copy
// (summary differences, shared points matched by reference position, the 4 x 4 flag table),
// and missing or unreadable inputs.
#include "analysis/compare_runs.h"
#include "analysis/slice_profiles.h"

#include "synthetic_run.h"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

namespace
{
using namespace vulnus::testing;

struct Result
{
  int status;
  std::string out, err;
};

Result compare(const std::filesystem::path& a, const std::filesystem::path& b)
{
  std::ostringstream out, err;
  const int status = vulnus::analysis::compare_runs(a.string(), b.string(), out, err);
  return {status, out.str(), err.str()};
}

/// The whitespace-separated fields of the output line whose first field is `key`.
std::vector<std::string> row(const std::string& text, const std::string& key)
{
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    std::istringstream fields(line);
    std::vector<std::string> row;
    for (std::string field; fields >> field;)
      row.push_back(field);
    if (!row.empty() && row[0] == key)
      return row;
  }
  return {};
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

TEST(CompareRuns, RunWithItselfHasNoDifferences)
{
  const Scratch scratch;
  const auto run = scratch.make("run");
  write_wound_run(run);
  const Result result = compare(run, run);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(result.err.empty());
  EXPECT_TRUE(contains(result.out, " 0 differ, 0 in one run only")) << result.out;
  for (const char* key : {"failed.total", "exit_wound.aspect_ratio", "tract.area_m2[2]",
                          "completed", "energy.balance_error"})
  {
    const auto fields = row(result.out, key);
    ASSERT_EQ(fields.size(), 5u) << key << "\n" << result.out;
    EXPECT_EQ(fields[1], fields[2]) << key;
    EXPECT_EQ(fields[3], "0") << key;
    EXPECT_EQ(fields[4], "0") << key;
  }
  // The last particle file (00001, with the wound) is compared: 1008 points, all the same.
  EXPECT_TRUE(contains(result.out, "particles_00001.h5")) << result.out;
  EXPECT_TRUE(contains(result.out, "shared 1008 ")) << result.out;
  EXPECT_TRUE(contains(result.out, "same id 1008)")) << result.out;
  EXPECT_TRUE(contains(result.out, "same flag: 1008 of 1008 (100.000 %)")) << result.out;
  const auto total = row(result.out, "total");
  ASSERT_EQ(total.size(), 5u) << result.out;
  EXPECT_EQ(total[1], "0");
  EXPECT_EQ(total[2], "0");
  EXPECT_EQ(total[3], "0");
  EXPECT_NE(total[4], "0");
}

TEST(CompareRuns, PerturbedCopyShowsTheDifferences)
{
  const Scratch scratch;
  const auto a = scratch.make("a"), b = scratch.make("b");
  write_summary(a, {{"failed", {{"matrix", 10}, {"fiber", 0}, {"total", 20}}},
                    {"energy", {{"balance_error", 0.01}}},
                    {"tract", {{"area_m2", {1e-4, 2e-4}}}},
                    {"warnings", nlohmann::json::array()},
                    {"completed", true}});
  write_summary(b, {{"failed", {{"matrix", 10}, {"fiber", 3}, {"total", 25}}},
                    {"energy", {{"balance_error", 0.01}}},
                    {"tract", {{"area_m2", {1e-4, 2e-4, 3e-4}}}},
                    {"warnings", {"something"}},
                    {"completed", false}});
  // A: an older file that must be ignored, then the last one.
  write_particles(a / "particles_00000.h5", {{0, {0, 0, 0}, 3}}, 0.0);
  write_particles(a / "particles_00001.h5",
                  {{0, {0, 0, 0}, 0},
                   {1, {1e-3, 0, 0}, 1},
                   {2, {2e-3, 0, 0}, 2},
                   {3, {3e-3, 0, 0}, 3},
                   {4, {4e-3, 0, 0}, 3},
                   {5, {5e-3, 0, 0}, 0},     // only in A
                   {7, {7e-3, 0, 0}, 0, 1}}, // bullet in A, slab in B: not shared
                  1e-4);
  // B: another order, one other id, a rounding-size shift, one point only in B.
  write_particles(b / "particles_00003.h5",
                  {{6, {6e-3, 0, 0}, 3}, // only in B
                   {4, {4e-3, 0, 0}, 3},
                   {3, {3e-3, 1e-9, 0}, 1}, // total -> matrix
                   {2, {2e-3, 0, 0}, 2},
                   {1, {1e-3, 0, 0}, 0}, // matrix -> intact
                   {50, {0, 0, 0}, 0},   // same point, other id
                   {7, {7e-3, 0, 0}, 0, 0}},
                  1.1e-4);
  const Result result = compare(a, b);
  ASSERT_EQ(result.status, 0) << result.err;

  const auto total = row(result.out, "failed.total");
  ASSERT_EQ(total.size(), 5u) << result.out;
  EXPECT_EQ(total[1], "20");
  EXPECT_EQ(total[2], "25");
  EXPECT_EQ(total[3], "5");
  EXPECT_EQ(total[4], "0.25");
  EXPECT_EQ(row(result.out, "failed.fiber").at(4), "inf");
  EXPECT_EQ(row(result.out, "failed.matrix").at(3), "0");
  EXPECT_EQ(row(result.out, "completed").at(3), "-1");
  const auto extra = row(result.out, "tract.area_m2[2]");
  ASSERT_GE(extra.size(), 4u) << result.out;
  EXPECT_EQ(extra[1], "-");
  EXPECT_TRUE(contains(result.out, "only in B")) << result.out;
  EXPECT_TRUE(contains(result.out, "8 numbers: 3 differ, 1 in one run only")) << result.out;

  EXPECT_TRUE(contains(result.out, "particles_00001.h5")) << result.out;
  EXPECT_TRUE(contains(result.out, "particles_00003.h5")) << result.out;
  EXPECT_TRUE(contains(result.out, "points: A 7, B 7; shared 5 ")) << result.out;
  EXPECT_TRUE(contains(result.out, "same id 4)")) << result.out;
  EXPECT_TRUE(contains(result.out, "only in A 2, only in B 2")) << result.out;
  EXPECT_TRUE(contains(result.out, "same flag: 3 of 5 (60.000 %)")) << result.out;
  const std::vector<std::vector<std::string>> expected{{"intact", "1", "0", "0", "0"},
                                                       {"matrix", "1", "0", "0", "0"},
                                                       {"fiber", "0", "0", "1", "0"},
                                                       {"total", "0", "1", "0", "1"}};
  for (const auto& line : expected)
    EXPECT_EQ(row(result.out, line[0]), line) << result.out;
}

TEST(SliceProfiles, RebinningTakesOverlapWeightedMeans)
{
  using vulnus::analysis::rebin_slices;
  // 1 mm slices [0, 1], [1, 2] onto 1.5 mm slices [0, 1.5], [1.5, 3]: the first takes 1 mm of
  // the value 1 and 0.5 mm of 3; the second is not covered whole.
  const auto coarser = rebin_slices({0.5e-3, 1.5e-3}, {1.0, 3.0}, {0.75e-3, 2.25e-3});
  ASSERT_EQ(coarser.size(), 2u);
  ASSERT_TRUE(coarser[0].has_value());
  EXPECT_NEAR(*coarser[0], (1.0 * 1.0 + 0.5 * 3.0) / 1.5, 1e-12);
  EXPECT_FALSE(coarser[1].has_value());
  // Onto finer slices: each takes the value of the slice it lies in.
  const auto finer = rebin_slices({0.5e-3, 1.5e-3}, {1.0, 3.0}, {0.25e-3, 0.75e-3, 1.25e-3});
  ASSERT_EQ(finer.size(), 3u);
  EXPECT_DOUBLE_EQ(finer[0].value(), 1.0);
  EXPECT_DOUBLE_EQ(finer[1].value(), 1.0);
  EXPECT_DOUBLE_EQ(finer[2].value(), 3.0);
  EXPECT_TRUE(vulnus::analysis::same_slices({0.5e-3, 1.5e-3}, {0.5e-3, 1.5e-3 + 1e-15}));
  EXPECT_FALSE(vulnus::analysis::same_slices({0.5e-3, 1.5e-3}, {0.25e-3, 0.75e-3}));
  EXPECT_THROW(rebin_slices({0.5e-3}, {1.0, 2.0}, {0.5e-3}), std::invalid_argument);
}

TEST(CompareRuns, TractsSlicedAtOtherCellSizesCompareDepthForDepth)
{
  const Scratch scratch;
  const auto coarse = scratch.make("coarse"), fine = scratch.make("fine"),
             longer = scratch.make("longer");
  write_summary(coarse, {{"tract", {{"depth_m", {5e-4, 1.5e-3}}, {"area_m2", {2e-5, 4e-5}}}}});
  // Half-thickness slices whose pairs average to the coarse run's areas, and one slice more.
  write_summary(fine, {{"tract",
                        {{"depth_m", {2.5e-4, 7.5e-4, 1.25e-3, 1.75e-3, 2.25e-3}},
                         {"area_m2", {1e-5, 3e-5, 3.5e-5, 4.5e-5, 9e-5}}}}});
  write_summary(
      longer, {{"tract", {{"depth_m", {5e-4, 1.5e-3, 2.5e-3}}, {"area_m2", {2e-5, 4e-5, 5e-5}}}}});
  Result result = compare(coarse, fine);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "(A: 2 slices of 1 mm, B: 5 slices of 0.5 mm)")) << result.out;
  for (const char* key : {"tract.area_m2[0]", "tract.area_m2[1]", "tract.depth_m[1]"})
    EXPECT_EQ(row(result.out, key).at(4), "0") << key << "\n" << result.out;
  EXPECT_TRUE(contains(result.out, "4 numbers: 0 differ, 0 in one run only")) << result.out;

  // A deeper than B: the slice B covers only half of has no value of B's.
  result = compare(longer, fine);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(row(result.out, "tract.area_m2[1]").at(4), "0") << result.out;
  const auto beyond = row(result.out, "tract.area_m2[2]");
  ASSERT_GE(beyond.size(), 4u) << result.out;
  EXPECT_EQ(beyond[2], "-") << result.out;
  EXPECT_EQ(beyond[3], "only") << result.out;
  // B against A: B's five slices take the coarse values, the last one none.
  result = compare(fine, coarse);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(row(result.out, "tract.area_m2[2]").at(2), "4e-05") << result.out;
  EXPECT_EQ(row(result.out, "tract.area_m2[4]").at(3), "only") << result.out;

  // Same slicing: nothing is re-binned and no note is printed.
  result = compare(coarse, coarse);
  EXPECT_FALSE(contains(result.out, "note:")) << result.out;
}

TEST(CompareRuns, PenetrationCurvesCompareAtTheSameDepths)
{
  // Two velocity-depth curves sampled at different depths, both v = 100 - 1e4 d (m/s, m):
  // at the same fractions of the shallower deepest point (2 mm) they agree exactly; the
  // per-slice cavity lists are not compared index by index.
  const Scratch scratch;
  const auto a = scratch.make("a"), b = scratch.make("b");
  write_summary(a, {{"penetration", {{"depth_m", 2e-3}, {"curve", {{"depth_m", {0.0, 1e-3, 2e-3}},
                                                                  {"velocity_m_s", {100.0, 90.0, 80.0}},
                                                                  {"time_s", {0.0, 1e-5, 2e-5}}}}}},
                    {"temporary_cavity", {{"depth_m", {5e-4}}, {"max_diameter_m", {3e-3}}}}});
  write_summary(b, {{"penetration", {{"depth_m", 3e-3}, {"curve", {{"depth_m", {0.0, 0.8e-3, 3e-3}},
                                                                  {"velocity_m_s", {100.0, 92.0, 70.0}},
                                                                  {"time_s", {0.0, 1e-5, 3e-5}}}}}},
                    {"temporary_cavity", {{"depth_m", {5e-4, 1.5e-3}}, {"max_diameter_m", {3e-3, 4e-3}}}}});
  const Result result = compare(a, b);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "shallower run's deepest point (2 mm)")) << result.out;
  for (const char* key : {"penetration.velocity_m_s_at_depth_fraction_0.00",
                          "penetration.velocity_m_s_at_depth_fraction_0.25",
                          "penetration.velocity_m_s_at_depth_fraction_0.75",
                          "penetration.velocity_m_s_at_depth_fraction_1.00"})
    EXPECT_EQ(row(result.out, key).at(4), "0") << key << "\n" << result.out;
  EXPECT_EQ(row(result.out, "penetration.velocity_m_s_at_depth_fraction_0.50").at(1), "90");
  EXPECT_FALSE(contains(result.out, "curve.depth_m")) << result.out;
  EXPECT_FALSE(contains(result.out, "temporary_cavity.max_diameter_m")) << result.out;
}

TEST(CompareRuns, WithoutParticleFilesComparesSummariesOnly)
{
  const Scratch scratch;
  const auto a = scratch.make("a"), b = scratch.make("b");
  write_summary(a, {{"steps", 10}});
  write_summary(b, {{"steps", 12}});
  const Result result = compare(a, b);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(row(result.out, "steps").at(3), "2");
  EXPECT_TRUE(contains(result.out, "failure flags: not compared")) << result.out;
}

TEST(CompareRuns, MissingOrUnreadableInputsGiveStatus2)
{
  const Scratch scratch;
  const auto good = scratch.make("good"), no_summary = scratch.make("no_summary"),
             bad_json = scratch.make("bad_json"), bad_h5 = scratch.make("bad_h5");
  write_wound_run(good);
  write_text(bad_json / "summary.json", "{ not json");
  write_summary(bad_h5, {{"steps", 1}});
  write_text(bad_h5 / "particles_00004.h5", "not an HDF5 file");

  Result result = compare(good, good.parent_path() / "does_not_exist");
  EXPECT_EQ(result.status, 2);
  EXPECT_TRUE(contains(result.err, "does_not_exist' is not a run directory")) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;

  result = compare(no_summary, good);
  EXPECT_EQ(result.status, 2);
  EXPECT_TRUE(contains(result.err, "no_summary/summary.json' (missing")) << result.err;

  result = compare(good, bad_json);
  EXPECT_EQ(result.status, 2);
  EXPECT_TRUE(contains(result.err, "is not valid JSON")) << result.err;

  result = compare(good, bad_h5);
  EXPECT_EQ(result.status, 2);
  EXPECT_TRUE(contains(result.err, "particles_00004.h5' as an HDF5 file")) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
}
} // namespace

TEST(CompareRuns, FaceWoundsMeasuredInOtherLayersAreNoted)
{
  const Scratch scratch;
  const auto old_run = scratch.make("old"), one_mm = scratch.make("one_mm"),
             two_mm = scratch.make("two_mm");
  write_summary(old_run, {{"exit_wound", {{"aspect_ratio", 1.2}}}});
  write_summary(one_mm, {{"exit_wound", {{"aspect_ratio", 1.1}}}, {"wound_face_layer_m", 1e-3}});
  write_summary(two_mm, {{"exit_wound", {{"aspect_ratio", 1.0}}}, {"wound_face_layer_m", 2e-3}});
  Result result = compare(one_mm, two_mm);
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "different depth (A: 1 mm, B: 2 mm)")) << result.out;
  result = compare(old_run, one_mm);
  EXPECT_TRUE(contains(result.out, "(A: one cell (run before the entry), B: 1 mm)")) << result.out;
  result = compare(one_mm, one_mm);
  EXPECT_FALSE(contains(result.out, "note:")) << result.out;
}
