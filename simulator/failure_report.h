// What a run reports when a step throws: the kind of failure and a message short enough for
// a terminal. deal.II's exceptions carry a page of source locations and a stack trace; the
// report keeps their "Additional information" (or the violated condition).
#pragma once

#include <exception>
#include <string>

namespace vulnus::simulator
{
struct FailureReport
{
  std::string kind;    ///< "blow-up", "FE solver failure" or "breakdown"
  std::string message; ///< one paragraph
};

FailureReport describe_failure(const std::exception& error);
} // namespace vulnus::simulator
