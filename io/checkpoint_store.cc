// Checkpoint files of a run: naming, atomic writing, pruning and newest-complete lookup.
#include "io/checkpoint_store.h"

#include "io/atomic_file.h"
#include "mpm/binary_io.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace vulnus::io
{
namespace
{
using namespace mpm::binary;

// Format 2 added the mesh output list, format 3 the temporary cavity's record, format 4 the
// run's warnings; older files are refused by name.
constexpr char header_tag[8] = {'V', 'U', 'L', 'N', 'R', 'U', 'N', '4'};
constexpr char format_1_tag[8] = {'V', 'U', 'L', 'N', 'R', 'U', 'N', '1'};
constexpr char format_2_tag[8] = {'V', 'U', 'L', 'N', 'R', 'U', 'N', '2'};
constexpr char format_3_tag[8] = {'V', 'U', 'L', 'N', 'R', 'U', 'N', '3'};
constexpr char trailer_tag[8] = {'V', 'U', 'L', 'N', 'E', 'N', 'D', '1'};
constexpr const char* prefix = "step_";
constexpr const char* suffix = ".chk";
} // namespace

CheckpointStore::CheckpointStore(const std::string& run_directory, const unsigned int keep,
                                 const std::string& folder_name)
    : folder((std::filesystem::path(run_directory) / folder_name).string()), keep(std::max(1u, keep))
{
}

std::string CheckpointStore::write(const std::uint64_t step, const RunProgress& progress,
                                   const std::function<void(std::ostream&)>& write_state) const
{
  std::filesystem::create_directories(folder);
  char name[40];
  std::snprintf(name, sizeof(name), "%s%010llu%s", prefix, static_cast<unsigned long long>(step), suffix);
  const std::string path = (std::filesystem::path(folder) / name).string();
  write_file_atomically(path,
                        [&](std::ostream& out)
                        {
                          out.write(header_tag, sizeof(header_tag));
                          put_text(out, progress.resolved_deck);
                          put(out, progress.next_output);
                          put(out, progress.history_bytes);
                          put(out, progress.wall_seconds);
                          put_text(out, progress.output_records);
                          put_text(out, progress.mesh_output_records);
                          put_vector(out, progress.cavity_record);
                          put(out, static_cast<std::uint64_t>(progress.warnings.size()));
                          for (const std::string& warning : progress.warnings)
                            put_text(out, warning);
                          put(out, static_cast<std::uint8_t>(progress.energy_warned));
                          write_state(out);
                          out.write(trailer_tag, sizeof(trailer_tag));
                        });
  const std::vector<std::string> all = files();
  for (std::size_t i = keep; i < all.size(); ++i)
    std::filesystem::remove(all[i]);
  return path;
}

std::vector<std::string> CheckpointStore::files() const
{
  std::vector<std::string> found;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    return found;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
  {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind(prefix, 0) == 0 && name.size() > std::strlen(suffix) &&
        name.compare(name.size() - std::strlen(suffix), std::string::npos, suffix) == 0)
      found.push_back(entry.path().string());
  }
  // Zero-padded step numbers: the lexical order is the step order.
  std::sort(found.rbegin(), found.rend());
  return found;
}

std::string CheckpointStore::newest_deck() const
{
  for (const std::string& candidate : files())
  {
    try
    {
      std::ifstream in(candidate, std::ios::binary);
      if (!in)
        continue;
      expect_tag(in, header_tag, "it is not a vulnus run checkpoint");
      std::string deck;
      get_text(in, deck);
      return deck;
    }
    catch (const std::exception&)
    {
      // a damaged header: read_newest reports it when it skips the file
    }
  }
  return "";
}

RunProgress CheckpointStore::read_newest(const std::function<void(std::istream&)>& read_state,
                                         const std::function<void(const std::string&)>& warn,
                                         std::string& path) const
{
  const std::vector<std::string> candidates = files();
  for (const std::string& candidate : candidates)
  {
    try
    {
      std::ifstream in(candidate, std::ios::binary);
      if (!in)
        throw std::runtime_error("it cannot be opened");
      char tag[sizeof(header_tag)] = {};
      in.read(tag, sizeof(tag));
      if (in && std::equal(tag, tag + sizeof(tag), format_1_tag))
        throw std::runtime_error("it was written by an older vulnus (checkpoint format 1, "
                                 "without the mesh output list)");
      if (in && std::equal(tag, tag + sizeof(tag), format_2_tag))
        throw std::runtime_error("it was written by an older vulnus (checkpoint format 2, "
                                 "without the temporary cavity's record)");
      if (in && std::equal(tag, tag + sizeof(tag), format_3_tag))
        throw std::runtime_error("it was written by an older vulnus (checkpoint format 3, "
                                 "without the run's warnings)");
      if (!in || !std::equal(tag, tag + sizeof(tag), header_tag))
        throw std::runtime_error("it is not a vulnus run checkpoint");
      RunProgress progress;
      get_text(in, progress.resolved_deck);
      get(in, progress.next_output);
      get(in, progress.history_bytes);
      get(in, progress.wall_seconds);
      get_text(in, progress.output_records);
      get_text(in, progress.mesh_output_records);
      get_vector(in, progress.cavity_record);
      progress.warnings.resize(get_length(in, std::uint64_t(1) << 20));
      for (std::string& warning : progress.warnings)
        get_text(in, warning);
      std::uint8_t energy_warned = 0;
      get(in, energy_warned);
      progress.energy_warned = energy_warned != 0;
      read_state(in);
      expect_tag(in, trailer_tag, "it is incomplete (no end tag)");
      path = candidate;
      return progress;
    }
    catch (const std::exception& error)
    {
      warn("checkpoint '" + candidate + "' skipped: " + error.what());
    }
  }
  throw std::runtime_error(candidates.empty()
                             ? "no checkpoint in '" + folder +
                                 "' (a run writes them at Output/Checkpoint step interval or "
                                 "Checkpoint wall interval, and when stopped by SIGINT/SIGTERM)"
                             : "no complete checkpoint in '" + folder + "'");
}
} // namespace vulnus::io
