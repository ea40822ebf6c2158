// Atomic file writing (temporary name, fsync, rename).
#include "io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace vulnus::io
{
namespace
{
/// Flush the file's data to disk so the rename cannot expose an empty file after a crash.
void sync_file(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0)
    return;
  ::fsync(fd);
  ::close(fd);
}

} // namespace

void rename_into_place(const std::string& tmp, const std::string& path)
{
  sync_file(tmp);
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "': " + reason);
  }
}

std::string temporary_name(const std::string& path)
{
  return path + ".tmp";
}

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& writer)
{
  const std::string tmp = temporary_name(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw std::runtime_error("cannot open '" + tmp + "' for writing: " + std::strerror(errno));
    try
    {
      writer(out);
    }
    catch (...)
    {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    out.flush();
    if (!out)
    {
      out.close();
      std::remove(tmp.c_str());
      throw std::runtime_error("error while writing '" + tmp + "'");
    }
  }
  rename_into_place(tmp, path);
}

void write_file_atomically_by_name(const std::string& path,
                                   const std::function<void(const std::string&)>& writer)
{
  const std::string tmp = temporary_name(path);
  try
  {
    writer(tmp);
  }
  catch (...)
  {
    std::remove(tmp.c_str());
    throw;
  }
  rename_into_place(tmp, path);
}
} // namespace vulnus::io
