// Atomic file writing: write to `name.tmp` in the same directory, flush, then rename onto the
// final name, so a crash never leaves a half-written file under a final name.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace vulnus::io
{
/// Write `path` atomically through a stream: `writer` fills the stream of `path.tmp`, which is
/// then flushed, synced and renamed onto `path`. Throws std::runtime_error (naming the file
/// and the system error) if the file cannot be written; the temporary is removed then.
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& writer);

/// Atomic writing for writers that need a file name rather than a stream (HDF5): `writer`
/// creates and closes the file it is given (`path.tmp`), which is then renamed onto `path`.
void write_file_atomically_by_name(const std::string& path,
                                   const std::function<void(const std::string&)>& writer);

/// Name of the temporary file used for `path`.
std::string temporary_name(const std::string& path);

/// Moves a finished temporary file to `path` (data synced first, then an atomic rename).
void rename_into_place(const std::string& tmp, const std::string& path);
} // namespace vulnus::io
