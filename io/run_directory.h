// The run directory of one `vulnus run`: created on demand, holds deck_used.prm (every
// parameter as resolved), log.txt (a tee of the terminal messages) and the outputs.
#pragma once

#include <fstream>
#include <functional>
#include <mutex>
#include <string>

namespace vulnus::io
{
/// `runs/<deck stem>` for a deck path such as `inputs/paper/anisotropic_150ms.prm`.
std::string default_run_directory(const std::string& deck_path);

class RunDirectory
{
public:
  /// Create `path` (and its parents) and open log.txt for appending. Throws
  /// std::runtime_error naming the directory if it cannot be created. With `writes` false
  /// (the ranks other than 0 of an MPI run) log, warn and write_deck_used do nothing.
  explicit RunDirectory(const std::string& path, bool writes = true);

  /// False on the MPI ranks that leave the run's own files to rank 0.
  bool writes_files() const { return writer; }

  const std::string& path() const { return directory; }

  /// `path()/name`.
  std::string file(const std::string& name) const;

  /// Write deck_used.prm atomically.
  void write_deck_used(const std::string& resolved_deck) const;

  /// Print a line on the terminal (stdout) and append it to log.txt. Thread-safe.
  void log(const std::string& line);

  /// Same as log() but on stderr, prefixed with "warning: ".
  void warn(const std::string& line);

  /// log() as a callable, for code that must not depend on this class.
  std::function<void(const std::string&)> logger();

private:
  std::string directory;
  bool writer = true;
  std::ofstream log_file;
  std::mutex log_mutex;
};
} // namespace vulnus::io
