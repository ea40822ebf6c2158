// The bad-deck corpus: every tests/decks/bad/NAME.prm must make `vulnus run` exit with status 2,
// print the substring held in NAME.expected, and write nothing.
#include "command_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace
{
using namespace vulnus::testing;
namespace fs = std::filesystem;

std::string first_line(const std::string& text)
{
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
    line.pop_back();
  return line;
}

TEST(BadDecks, EachFailsWithItsMessageAndWritesNothing)
{
  const fs::path corpus = fs::path(source_dir()) / "tests/decks/bad";
  std::vector<fs::path> decks;
  for (const auto& entry : fs::directory_iterator(corpus))
    if (entry.path().extension() == ".prm")
      decks.push_back(entry.path());
  std::sort(decks.begin(), decks.end());
  ASSERT_GE(decks.size(), 10u) << "corpus in " << corpus;

  ScratchDirectory scratch("bad_decks");
  for (const fs::path& deck : decks)
  {
    SCOPED_TRACE(deck.filename().string());
    const fs::path expected_file = fs::path(deck).replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected_file)) << "missing " << expected_file;
    const std::string expected = first_line(read_text(expected_file));
    ASSERT_FALSE(expected.empty());

    const fs::path output = scratch.path / deck.stem();
    const CommandResult result =
        run_vulnus("run '" + deck.string() + "' --output '" + output.string() + "'", scratch.path);
    EXPECT_EQ(result.exit_status, 2) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << "expected <" << expected << "> in:\n"
                                                            << result.err;
    EXPECT_FALSE(fs::exists(output)) << "the run directory was created";
    EXPECT_EQ(result.out, "");
  }
  EXPECT_EQ(n_entries(scratch.path), 0u);
}
} // namespace
