// Free-space check before large outputs.
#include "io/disk_space.h"

#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace vulnus::io
{
void require_free_space(const std::string& directory, const double bytes, const std::string& what)
{
  std::error_code code;
  const std::filesystem::space_info space = std::filesystem::space(directory, code);
  if (code || double(space.available) >= 1.1 * bytes)
    return;
  std::ostringstream o;
  o << "not enough disk space for " << what << ": " << std::fixed << std::setprecision(2)
    << double(space.available) / 1e9 << " GB free in '" << directory << "', about "
    << bytes / 1e9 << " GB needed; free some space or write less often (a larger "
    << "Output/Particle output interval)";
  throw std::runtime_error(o.str());
}
} // namespace vulnus::io
