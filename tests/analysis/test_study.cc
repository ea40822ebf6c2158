// scripts/study checks every combination before running any: the shipped study files
// (inputs/studies/*.args) pass, a combination with a bad value is refused with the entry named,
// exit status 2 and no run directory.
#include "script_shell.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace
{
namespace fs = std::filesystem;
using namespace vulnus::testing;

/// Runs scripts/study from the source directory with `arguments`, output into `log`.
int study(const std::string& arguments, const fs::path& log)
{
  return shell("cd '" + source_directory() + "' && scripts/study --vulnus '" +
               VULNUS_DEFAULT_BINARY + "' " + arguments + " > '" + log.string() + "' 2>&1");
}

TEST(Study, EveryShippedStudyFilePassesTheCheck)
{
  const fs::path log = fs::temp_directory_path() / "vulnus_study_check.log";
  int n_files = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(source_directory() +
                                                                 "/inputs/studies"))
  {
    if (entry.path().extension() != ".args")
      continue;
    ++n_files;
    EXPECT_EQ(study("@'" + entry.path().string() + "' --check", log), 0)
      << entry.path() << ":\n" << read_text(log);
    EXPECT_NE(read_text(log).find("all 3 combinations pass"), std::string::npos)
      << read_text(log);
  }
  // side faces, slab size (paper and water-stiff tissue), bulk modulus, failure measure
  EXPECT_EQ(n_files, 6);
}

TEST(Study, RefusedCombinationStopsTheStudyBeforeAnyRun)
{
  const fs::path output = fs::temp_directory_path() / "vulnus_study_refused";
  const fs::path log = fs::temp_directory_path() / "vulnus_study_refused.log";
  fs::remove_all(output);
  EXPECT_EQ(study("@inputs/studies/bulk_modulus.args --vary 'Time/CFL=0.4,1.5' --output '" +
                    output.string() + "'",
                  log),
            2);
  const std::string text = read_text(log);
  EXPECT_NE(text.find("Time/CFL = '1.5' is not valid"), std::string::npos) << text;
  EXPECT_NE(text.find("3 of 6 combinations refused; nothing was run"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(output));
}
} // namespace
