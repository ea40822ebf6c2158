// A check before large outputs: is there room for them where the run writes? A full disk
// otherwise shows as an HDF5 write error deep inside the library.
#pragma once

#include <string>

namespace vulnus::io
{
/// Throws std::runtime_error naming `what`, the free and the needed space when the file
/// system holding `directory` has less than `bytes` (plus a 10 % margin) available.
void require_free_space(const std::string& directory, double bytes, const std::string& what);
} // namespace vulnus::io
