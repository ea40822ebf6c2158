// scripts/plot-wound on small synthetic run directories: every picture written as a non-empty
// PNG; a directory without run files is refused with exit status 2; a run without particle
// files still gets its tract and history pictures. Skipped only where Debian's python3 lacks
// matplotlib or h5py.
#include "script_shell.h"
#include "synthetic_run.h"

#include <gtest/gtest.h>


namespace
{
using namespace vulnus::testing;

/// Runs plot-wound on `run` (PNGs into run/plots), its output into `log`.
int plot_wound(const std::filesystem::path& run, const std::filesystem::path& log)
{
  return shell("'" + source_directory() + "/scripts/plot-wound' '" + run.string() + "' --output '" +
               (run / "plots").string() + "' > '" + log.string() + "' 2>&1");
}

bool is_png(const std::filesystem::path& path)
{
  const std::string text = read_text(path);
  return text.size() > 1000 && text.compare(1, 3, "PNG") == 0;
}

class PlotWound : public ::testing::Test
{
protected:
  void SetUp() override
  {
    // The script runs Debian's interpreter (see its first line).
    if (shell("/usr/bin/python3 -c 'import matplotlib, h5py' > /dev/null 2>&1") != 0)
      GTEST_SKIP() << "/usr/bin/python3 cannot import matplotlib and h5py: install "
                      "python3-matplotlib python3-h5py (scripts/setup) to test plot-wound";
  }
};

TEST_F(PlotWound, WritesEveryPicture)
{
  const Scratch scratch;
  const auto run = scratch.make("run");
  write_wound_run(run);
  ASSERT_EQ(plot_wound(run, run / "plot.log"), 0) << read_text(run / "plot.log");
  for (const char* name : {"wound_cuts.png", "wound_3d.png", "entrance_face.png", "exit_face.png",
                           "tract_area.png", "history.png"})
    EXPECT_TRUE(is_png(run / "plots" / name)) << name << "\n" << read_text(run / "plot.log");
}

TEST_F(PlotWound, SkipsPicturesWhoseDataIsMissing)
{
  const Scratch scratch;
  const auto run = scratch.make("run");
  write_wound_run(run);
  std::filesystem::remove(run / "particles_00000.h5");
  std::filesystem::remove(run / "particles_00001.h5");
  ASSERT_EQ(plot_wound(run, run / "plot.log"), 0) << read_text(run / "plot.log");
  EXPECT_TRUE(is_png(run / "plots" / "tract_area.png"));
  EXPECT_TRUE(is_png(run / "plots" / "history.png"));
  EXPECT_FALSE(std::filesystem::exists(run / "plots" / "wound_cuts.png"));
  EXPECT_NE(read_text(run / "plot.log").find("skipped the wound pictures"), std::string::npos)
      << read_text(run / "plot.log");
}

TEST_F(PlotWound, RefusesADirectoryWithoutRunFiles)
{
  const Scratch scratch;
  const auto run = scratch.make("empty");
  EXPECT_EQ(plot_wound(run, run / "plot.log"), 2);
  EXPECT_NE(read_text(run / "plot.log").find("not a vulnus run directory"), std::string::npos)
      << read_text(run / "plot.log");
  EXPECT_EQ(plot_wound(run / "missing", "/dev/null"), 2);
}
} // namespace
