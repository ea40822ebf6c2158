// CSV time history writer (whole lines, appended with POSIX write()).
#include "io/csv_history.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace vulnus::io
{
std::string CsvHistory::header_line(const std::string& path, const std::vector<std::string>& columns)
{
  if (columns.empty())
    throw std::invalid_argument("CSV history '" + path + "': no columns");
  std::string header;
  for (std::size_t c = 0; c < columns.size(); ++c)
  {
    if (columns[c].find_first_of(",\"\n\r") != std::string::npos)
      throw std::invalid_argument("CSV history '" + path + "': column name '" + columns[c] +
                                  "' contains a comma, quote or newline");
    header += (c == 0 ? "" : ",") + columns[c];
  }
  return header + '\n';
}

CsvHistory::CsvHistory(const std::string& path, const std::vector<std::string>& columns,
                       const unsigned int flush_every)
    : file_path(path), column_names(columns), flush_every(flush_every == 0 ? 1 : flush_every)
{
  const std::string header = header_line(path, columns);
  fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  write_all(header);
}

CsvHistory::CsvHistory(const std::string& path, const std::vector<std::string>& columns,
                       const unsigned int flush_every, const std::uint64_t keep_bytes)
    : file_path(path), column_names(columns), flush_every(flush_every == 0 ? 1 : flush_every)
{
  const std::string header = header_line(path, columns);
  fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CLOEXEC);
  if (fd < 0)
    throw std::runtime_error("cannot reopen the history '" + path + "': " + std::strerror(errno));
  struct stat status = {};
  std::string first(header.size(), '\0');
  const bool readable = ::fstat(fd, &status) == 0 &&
                        ::pread(fd, first.data(), first.size(), 0) == static_cast<ssize_t>(first.size());
  if (!readable || static_cast<std::uint64_t>(status.st_size) < keep_bytes || keep_bytes < header.size() ||
      first != header)
  {
    ::close(fd);
    fd = -1;
    throw std::runtime_error("the history '" + path +
                             "' does not hold the rows of the checkpoint (shorter file or other "
                             "columns); it cannot be continued");
  }
  if (::ftruncate(fd, static_cast<off_t>(keep_bytes)) != 0)
  {
    ::close(fd);
    fd = -1;
    throw std::runtime_error("cannot truncate '" + path + "': " + std::strerror(errno));
  }
  n_bytes_written = keep_bytes;
}

CsvHistory CsvHistory::resume(const std::string& path, const std::vector<std::string>& columns,
                              const std::uint64_t keep_bytes, const unsigned int flush_every)
{
  return CsvHistory(path, columns, flush_every, keep_bytes);
}

CsvHistory::CsvHistory(CsvHistory&& other) noexcept
    : file_path(std::move(other.file_path)), column_names(std::move(other.column_names)),
      flush_every(other.flush_every), fd(other.fd), buffer(std::move(other.buffer)),
      n_buffered(other.n_buffered), n_rows_written(other.n_rows_written),
      n_bytes_written(other.n_bytes_written)
{
  other.fd = -1;
  other.buffer.clear();
  other.n_buffered = 0;
}

CsvHistory::~CsvHistory()
{
  try
  {
    flush();
  }
  catch (...)
  {
    // A destructor must not throw; the rows already written stay valid.
  }
  if (fd >= 0)
    ::close(fd);
}

void CsvHistory::add_row(const std::vector<double>& values)
{
  if (values.size() != column_names.size())
    throw std::invalid_argument("CSV history '" + file_path + "': row has " +
                                std::to_string(values.size()) + " values for " +
                                std::to_string(column_names.size()) + " columns");
  char number[32];
  for (std::size_t c = 0; c < values.size(); ++c)
  {
    const int n = std::snprintf(number, sizeof(number), "%.12g", values[c]);
    if (c > 0)
      buffer += ',';
    buffer.append(number, static_cast<std::size_t>(n));
  }
  buffer += '\n';
  ++n_buffered;
  if (n_buffered >= flush_every)
    flush();
}

void CsvHistory::flush()
{
  if (buffer.empty())
    return;
  write_all(buffer);
  n_rows_written += n_buffered;
  buffer.clear();
  n_buffered = 0;
}

void CsvHistory::write_all(const std::string& text)
{
  std::size_t done = 0;
  while (done < text.size())
  {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0)
    {
      if (errno == EINTR)
        continue;
      throw std::runtime_error("cannot write to '" + file_path + "': " + std::strerror(errno));
    }
    done += static_cast<std::size_t>(n);
  }
  n_bytes_written += text.size();
}
} // namespace vulnus::io
