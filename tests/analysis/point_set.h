// A hand-built set of target points for the wound-metric tests: reference positions, volumes
// and failure flags, as compute_wound_metrics takes them.
#pragma once

#include "analysis/wound_metrics.h"

#include <cstdint>
#include <vector>

namespace vulnus::test
{
struct PointSet
{
  std::vector<analysis::Vector3> x;
  std::vector<double> volume;
  std::vector<std::uint8_t> flags;
};
} // namespace vulnus::test
