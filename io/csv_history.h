// CSV time history: a header row of named columns, then one row per recorded step. Rows are
// buffered as complete lines and appended with one write() per flush, so the file never ends
// in a torn line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vulnus::io
{
class CsvHistory
{
public:
  /// Create (truncate) `path` and write the header row. `flush_every` rows are buffered
  /// before they are written (1: write every row). Throws std::runtime_error if the file
  /// cannot be opened or a column name contains a comma, quote or newline.
  CsvHistory(const std::string& path, const std::vector<std::string>& columns,
             unsigned int flush_every = 20);
  ~CsvHistory();

  /// Continue the history of a restarted run: keep the first `keep_bytes` bytes of `path`
  /// (the header and the rows written up to the checkpoint, see bytes_written()), drop the
  /// rest and append from there. Throws std::runtime_error if the file is shorter or its
  /// header differs from `columns`.
  static CsvHistory resume(const std::string& path, const std::vector<std::string>& columns,
                           std::uint64_t keep_bytes, unsigned int flush_every = 20);

  CsvHistory(CsvHistory&& other) noexcept;
  CsvHistory(const CsvHistory&) = delete;
  CsvHistory& operator=(const CsvHistory&) = delete;

  /// Append one row; `values.size()` must equal the number of columns (else
  /// std::invalid_argument). Values are written with 12 significant digits.
  void add_row(const std::vector<double>& values);

  /// Write the buffered rows to the file now.
  void flush();

  const std::vector<std::string>& columns() const { return column_names; }
  std::size_t n_rows() const { return n_rows_written + n_buffered; }
  const std::string& path() const { return file_path; }
  /// Bytes in the file so far (header and flushed rows; call flush() first for all rows).
  std::uint64_t bytes_written() const { return n_bytes_written; }

private:
  CsvHistory(const std::string& path, const std::vector<std::string>& columns,
             unsigned int flush_every, std::uint64_t keep_bytes);
  static std::string header_line(const std::string& path, const std::vector<std::string>& columns);
  void write_all(const std::string& text);

  std::string file_path;
  std::vector<std::string> column_names;
  unsigned int flush_every;
  int fd = -1;
  std::string buffer;
  unsigned int n_buffered = 0;
  std::size_t n_rows_written = 0;
  std::uint64_t n_bytes_written = 0;
};
} // namespace vulnus::io
