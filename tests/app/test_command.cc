// The `vulnus` command line: help, version, usage errors, deck errors (exit status 2, message
// naming entry and line, nothing written), print/read round trip, --set overrides.
#include "command_runner.h"

#include <gtest/gtest.h>

#include <regex>

namespace
{
using namespace vulnus::testing;
namespace fs = std::filesystem;

TEST(Command, HelpAndVersion)
{
  ScratchDirectory scratch("help");
  const CommandResult help = run_vulnus("--help", scratch.path);
  EXPECT_EQ(help.exit_status, 0);
  EXPECT_NE(help.out.find("vulnus run DECK.prm"), std::string::npos);
  const CommandResult version = run_vulnus("--version", scratch.path);
  EXPECT_EQ(version.exit_status, 0);
  EXPECT_EQ(version.out.rfind("vulnus ", 0), 0u);
}

TEST(Command, UnknownSubcommandGivesUsageAndStatus2)
{
  ScratchDirectory scratch("unknown");
  const CommandResult result = run_vulnus("frobnicate", scratch.path);
  EXPECT_EQ(result.exit_status, 2);
  EXPECT_NE(result.err.find("unknown command 'frobnicate'"), std::string::npos);
  EXPECT_NE(result.err.find("Usage:"), std::string::npos);
  EXPECT_EQ(run_vulnus("", scratch.path).exit_status, 2);
  EXPECT_EQ(run_vulnus("run", scratch.path).exit_status, 2);
  EXPECT_EQ(run_vulnus("run a.prm --bogus", scratch.path).exit_status, 2);
}

TEST(Command, MissingAndUnreadableDeck)
{
  ScratchDirectory scratch("missing");
  CommandResult result = run_vulnus("run missing.prm", scratch.path);
  EXPECT_EQ(result.exit_status, 2);
  EXPECT_NE(result.err.find("missing.prm: cannot read the deck"), std::string::npos);
  EXPECT_EQ(n_entries(scratch.path), 0u);

  fs::create_directory(scratch.path / "a_directory.prm");
  result = run_vulnus("run a_directory.prm", scratch.path);
  EXPECT_EQ(result.exit_status, 2);
  EXPECT_NE(result.err.find("a_directory.prm: cannot read the deck"), std::string::npos);
  EXPECT_EQ(n_entries(scratch.path), 1u);
}

/// Writes `deck`, runs it, and checks the error kind: status 2, message, nothing written.
void expect_deck_error(const std::string& deck, const std::string& message)
{
  ScratchDirectory scratch("deck_error");
  write_text(scratch.path / "deck.prm", deck);
  const CommandResult result = run_vulnus("run deck.prm", scratch.path);
  EXPECT_EQ(result.exit_status, 2) << result.err;
  EXPECT_NE(result.err.find(message), std::string::npos) << "expected <" << message << "> in:\n"
                                                         << result.err;
  EXPECT_FALSE(fs::exists(scratch.path / "runs")) << "a run directory was created";
}

TEST(Command, DeckErrorsNameEntryLineAndExpectation)
{
  expect_deck_error("# c\nsubsection Grid\n  set Cel size = 0.001\nend\n",
                    "deck.prm:3: Grid/Cel size: no such entry in subsection 'Grid'; did you "
                    "mean 'Cell size'?");
  expect_deck_error("subsection Grid\n  set Cell size = -1\nend\n",
                    "deck.prm:2: Grid/Cell size = '-1' is not valid; expected a number >= 0");
  expect_deck_error("subsection Grid\n  set Update scheme = USF\nend\n",
                    "deck.prm:2: Grid/Update scheme = 'USF' is not valid; expected one of USL, "
                    "MUSL");
  expect_deck_error("\n\nsubsection Body bullet\n  set Material = steel\nend\n",
                    "deck.prm:4: Body bullet/Material: no material named 'steel'; use one of "
                    "the names in Scene/Materials (tissue, bullet)");
  expect_deck_error("subsection Time\n  set CFL = 1.5\nend\n",
                    "deck.prm:2: Time/CFL = '1.5' is not valid; expected a number in [0, 1]");
}

/// Overrides that shrink the reference scene to a run of a fraction of a second.
const std::string tiny_scene =
  "--set 'Grid/Cell size=0.005' --set 'Body slab/Particles per cell=1' "
  "--set 'Body bullet/Particles per cell=1' --set 'Time/End time=2e-6' "
  "--set 'Output/Particle output interval=1e-6'";

TEST(Command, PrintReadPrintIsIdentical)
{
  ScratchDirectory scratch("roundtrip");
  const CommandResult first = run_vulnus("--print-parameters defaults.prm", scratch.path);
  ASSERT_EQ(first.exit_status, 0) << first.err;
  const CommandResult second =
      run_vulnus("--print-parameters again.prm --deck defaults.prm", scratch.path);
  ASSERT_EQ(second.exit_status, 0) << second.err;
  const std::string printed = read_text(scratch.path / "defaults.prm");
  EXPECT_EQ(printed, read_text(scratch.path / "again.prm"));
  EXPECT_NE(printed.find("set Cell size"), std::string::npos);
  EXPECT_NE(printed.find("Allowed: "), std::string::npos);

  // The same text to the terminal; a run of the printed deck (made tiny by overrides) writes
  // as deck_used.prm exactly what --print-parameters gives for the deck and overrides.
  EXPECT_EQ(run_vulnus("--print-parameters", scratch.path).out, printed);
  const CommandResult run = run_vulnus("run defaults.prm " + tiny_scene, scratch.path);
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const CommandResult resolved =
    run_vulnus("--print-parameters resolved.prm --deck defaults.prm " + tiny_scene, scratch.path);
  ASSERT_EQ(resolved.exit_status, 0) << resolved.err;
  EXPECT_EQ(read_text(scratch.path / "runs/defaults/deck_used.prm"),
            read_text(scratch.path / "resolved.prm"));
  EXPECT_TRUE(fs::exists(scratch.path / "runs/defaults/log.txt"));
  for (const auto& entry : fs::directory_iterator(scratch.path / "runs/defaults"))
    EXPECT_NE(entry.path().extension(), ".tmp");
}

TEST(Command, SetOverridesTakeEffect)
{
  ScratchDirectory scratch("overrides");
  write_text(scratch.path / "deck.prm", "subsection Grid\n  set Cell size = 0.001\nend\n");
  const CommandResult result = run_vulnus(
      "run deck.prm " + tiny_scene + " --output out --threads 1 --set 'Grid/Cell size=0.002' "
      "--set 'Body bullet/Initial velocity=0, 50, 0' --set 'Material tissue/Transversely "
      "isotropic hyperelastic/Failure/Matrix shear limit=0.4'",
      scratch.path);
  ASSERT_EQ(result.exit_status, 0) << result.err;
  const std::string used = read_text(scratch.path / "out/deck_used.prm");
  EXPECT_TRUE(std::regex_search(used, std::regex("set Cell size *= 0.002 ")));
  EXPECT_TRUE(std::regex_search(used, std::regex("set Initial velocity *= 0, 50, 0 ")));
  EXPECT_TRUE(std::regex_search(used, std::regex("set Matrix shear limit *= 0.4 ")));
  EXPECT_TRUE(std::regex_search(used, std::regex("set Threads *= 1 ")));
  EXPECT_TRUE(std::regex_search(used, std::regex("set Directory *= out ")));
  EXPECT_FALSE(fs::exists(scratch.path / "runs"));
}

TEST(Command, CflAboveTheTestedRangeIsWarnedAndTheLogNamesSkippedWork)
{
  ScratchDirectory scratch("cfl_warning");
  write_text(scratch.path / "deck.prm", "subsection Grid\n  set Cell size = 0.002\nend\n");
  const CommandResult result = run_vulnus(
      "run deck.prm " + tiny_scene + " --output out --threads 1 --set 'Time/CFL=0.7'", scratch.path);
  ASSERT_EQ(result.exit_status, 0) << result.err;
  const std::string warning = "Time/CFL = 0.7 is above 0.5";
  EXPECT_NE((result.out + result.err).find(warning), std::string::npos) << result.out << result.err;
  EXPECT_NE(read_text(scratch.path / "out/summary.json").find(warning), std::string::npos);

  const CommandResult quiet =
      run_vulnus("run deck.prm " + tiny_scene + " --output out2 --threads 1", scratch.path);
  ASSERT_EQ(quiet.exit_status, 0) << quiet.err;
  EXPECT_EQ((quiet.out + quiet.err).find("is above 0.5"), std::string::npos);
  // The log names the work this scene does and skips.
  const std::string log = read_text(scratch.path / "out2/log.txt");
  EXPECT_NE(log.find("(transversely isotropic hyperelastic), failed tissue keeps its pressure in "
                     "compression"),
            std::string::npos)
    << log;
  EXPECT_NE(log.find("contact: multi-velocity field at nodes shared by bodies"), std::string::npos);
}

TEST(Command, BadOverridesAreRejectedLikeDeckLines)
{
  ScratchDirectory scratch("bad_overrides");
  write_text(scratch.path / "deck.prm", "");
  const std::pair<std::string, std::string> cases[] = {
      {"--set 'Grid/Cell size=abc'",
       "--set 'Grid/Cell size=abc': Grid/Cell size = 'abc' is not valid; expected a number"},
      {"--set 'Grid/Cel size=1'", "Grid/Cel size: no such entry in subsection 'Grid'"},
      {"--set 'Grid/Shape function=quadratic'", "expected one of linear, gimp"},
      {"--set 'Grid=1'", "is not a path Section/.../Entry"},
      {"--set 'Grid/Cell size'", "no '=' in the override"},
      {"--set 'Material steel/Model=rigid'", "there is no material named 'steel'"},
      {"--set 'Body bullet/Material=steel'",
       "--set 'Body bullet/Material=steel': Body bullet/Material: no material named 'steel'"},
      {"--threads -1", "--threads -1: Run/Threads = '-1' is not valid"},
  };
  for (const auto& [arguments, message] : cases)
  {
    const CommandResult result = run_vulnus("run deck.prm " + arguments, scratch.path);
    EXPECT_EQ(result.exit_status, 2) << arguments;
    EXPECT_NE(result.err.find(message), std::string::npos)
        << arguments << ": expected <" << message << "> in:\n"
        << result.err;
    EXPECT_EQ(n_entries(scratch.path), 1u) << arguments << ": something was written";
  }
}

TEST(Command, CheckValidatesWithoutWriting)
{
  ScratchDirectory scratch("check");
  write_text(scratch.path / "deck.prm", "subsection Time\n  set End time = 1e-4\nend\n");
  const CommandResult good = run_vulnus("check deck.prm", scratch.path);
  EXPECT_EQ(good.exit_status, 0) << good.err;
  const CommandResult bad = run_vulnus("check deck.prm --set 'Time/End time=0'", scratch.path);
  EXPECT_EQ(bad.exit_status, 2);
  EXPECT_NE(bad.err.find("Time/End time: must be > 0"), std::string::npos) << bad.err;
  EXPECT_EQ(n_entries(scratch.path), 1u);
}
} // namespace
