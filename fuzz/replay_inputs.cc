// Replays fuzz inputs (files or directories of files) through exercise_deck in a normal build:
// the regression test for every input that once crashed the fuzz target.
#include "fuzz/deck_exercise.h"

#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i)
  {
    if (fs::is_directory(argv[i]))
      for (const fs::directory_entry& entry : fs::directory_iterator(argv[i]))
        inputs.push_back(entry.path());
    else
      inputs.emplace_back(argv[i]);
  }
  if (inputs.empty())
  {
    std::cerr << "usage: replay_fuzz_inputs FILE_OR_DIRECTORY...\n";
    return 2;
  }
  int failures = 0;
  for (const fs::path& input : inputs)
  {
    std::ifstream file(input, std::ios::binary);
    if (!file)
    {
      std::cerr << input << ": cannot be read\n";
      ++failures;
      continue;
    }
    std::ostringstream text;
    text << file.rdbuf();
    try
    {
      vulnus::fuzz::exercise_deck(text.str());
      std::cout << input.filename().string() << ": handled\n";
    }
    catch (const std::exception& error)
    {
      std::cerr << input << ": unexpected exception: " << error.what() << '\n';
      ++failures;
    }
  }
  std::cout << inputs.size() - failures << " of " << inputs.size() << " inputs handled\n";
  return failures == 0 ? 0 : 1;
}
