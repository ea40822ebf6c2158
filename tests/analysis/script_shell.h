// Running the project's scripts from tests: the source directory, a shell command's exit
// status, a file's text.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace vulnus::testing
{
inline std::string source_directory()
{
  const char* from_environment = std::getenv("VULNUS_SOURCE_DIR");
  return from_environment ? from_environment : VULNUS_DEFAULT_SOURCE_DIR;
}

/// Exit status of a shell command (-1 when it did not exit normally).
inline int shell(const std::string& command)
{
  const int status = std::system(command.c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string read_text(const std::filesystem::path& path)
{
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}
} // namespace vulnus::testing
