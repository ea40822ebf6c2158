// CSV time history writer (whole lines, appended with POSIX write()).
#include "app/csv_history.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

namespace vulnus::app
{
CsvHistory::CsvHistory(const std::string& path, const std::vector<std::string>& columns,
                       const unsigned int flush_every)
    : file_path(path), column_names(columns), flush_every(flush_every == 0 ? 1 : flush_every)
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
  header += '\n';

  fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  write_all(header);
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
}
} // namespace vulnus::app
