// Rank and size from the launcher's environment variables.
#include "io/mpi_launch.h"

#include <cstdlib>

namespace vulnus::io
{
namespace
{
int first_variable(const char* const names[], const int fallback)
{
  for (int i = 0; names[i] != nullptr; ++i)
    if (const char* value = std::getenv(names[i]))
      return std::atoi(value);
  return fallback;
}
} // namespace

int launcher_rank()
{
  static const char* const names[] = {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", nullptr};
  return first_variable(names, 0);
}

int launcher_size()
{
  static const char* const names[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", nullptr};
  return first_variable(names, 1);
}
} // namespace vulnus::io
