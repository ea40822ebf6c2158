// The run directory: creation, deck_used.prm and the log tee.
#include "io/run_directory.h"

#include "io/atomic_file.h"

#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace vulnus::io
{
std::string default_run_directory(const std::string& deck_path)
{
  return (std::filesystem::path("runs") / std::filesystem::path(deck_path).stem()).string();
}

RunDirectory::RunDirectory(const std::string& path, const bool writes)
    : directory(path), writer(writes)
{
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw std::runtime_error("cannot create the run directory '" + directory +
                             "': " + (error ? error.message() : "not a directory"));
  if (!writer)
    return;
  log_file.open(file("log.txt"), std::ios::app);
  if (!log_file)
    throw std::runtime_error("cannot open '" + file("log.txt") + "' for writing");
}

std::string RunDirectory::file(const std::string& name) const
{
  return (std::filesystem::path(directory) / name).string();
}

void RunDirectory::write_deck_used(const std::string& resolved_deck) const
{
  if (!writer)
    return;
  write_file_atomically(file("deck_used.prm"), [&](std::ostream& out) { out << resolved_deck; });
}

void RunDirectory::log(const std::string& line)
{
  if (!writer)
    return;
  const std::lock_guard<std::mutex> lock(log_mutex);
  std::cout << line << '\n' << std::flush;
  log_file << line << '\n' << std::flush;
}

void RunDirectory::warn(const std::string& line)
{
  if (!writer)
    return;
  const std::lock_guard<std::mutex> lock(log_mutex);
  std::cerr << "warning: " << line << '\n' << std::flush;
  log_file << "warning: " << line << '\n' << std::flush;
}

std::function<void(const std::string&)> RunDirectory::logger()
{
  return [this](const std::string& line) { log(line); };
}
} // namespace vulnus::io
