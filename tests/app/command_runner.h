// Test helper: run the `vulnus` binary (env VULNUS_BINARY) in a scratch directory and capture
// its exit status, stdout and stderr.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace vulnus::testing
{
struct CommandResult
{
  int exit_status = -1;
  std::string out;
  std::string err;
};

inline std::string environment_or(const char* name, const char* fallback)
{
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

inline std::string vulnus_binary()
{
  return environment_or("VULNUS_BINARY", VULNUS_DEFAULT_BINARY);
}

inline std::string source_dir()
{
  return environment_or("VULNUS_SOURCE_DIR", VULNUS_DEFAULT_SOURCE_DIR);
}

inline std::string read_text(const std::filesystem::path& path)
{
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream(path) << text;
}

/// A fresh scratch directory per test, removed afterwards.
class ScratchDirectory
{
public:
  explicit ScratchDirectory(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("vulnus_app_test_" + name + "_" + std::to_string(::getpid())))
  {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(path); }
  std::filesystem::path path;
};

/// Run `vulnus ARGUMENTS` (already shell-quoted) with `directory` as working directory.
inline CommandResult run_vulnus(const std::string& arguments,
                                const std::filesystem::path& directory)
{
  const std::filesystem::path out = directory / ".stdout", err = directory / ".stderr";
  const std::string command = "cd '" + directory.string() + "' && '" + vulnus_binary() + "' " +
                              arguments + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

/// Entries of a directory except the captured stdout/stderr.
inline std::size_t n_entries(const std::filesystem::path& directory)
{
  std::size_t n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    if (entry.path().filename().string()[0] != '.')
      ++n;
  return n;
}
/// Starts `vulnus run ARGUMENTS` in `directory` without waiting; stdout and stderr go to
/// LOG.out and LOG.err there.
inline pid_t start_vulnus(const std::string& arguments, const std::filesystem::path& directory,
                          const std::string& log)
{
  const std::string command = "exec '" + vulnus_binary() + "' run " + arguments + " >'" +
                              (directory / (log + ".out")).string() + "' 2>'" +
                              (directory / (log + ".err")).string() + "'";
  const pid_t pid = fork();
  if (pid == 0)
  {
    if (chdir(directory.c_str()) != 0)
      _exit(127);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

/// Waits for a process of start_vulnus: its exit status (-1 when killed) and the signal
/// that killed it (0 when it exited).
inline int wait_for(const pid_t pid, int& signal)
{
  int status = 0;
  waitpid(pid, &status, 0);
  signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
} // namespace vulnus::testing
