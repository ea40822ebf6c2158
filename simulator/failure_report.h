// What a run reports when a step throws: the kind of failure and a message short enough for
// a terminal. deal.II's exceptions carry a page of source locations and a stack trace; the
// report keeps their "Additional information" (or the violated condition).
#pragma once

#include <exception>
#include <functional>
#include <string>

namespace vulnus::simulator
{
struct FailureReport
{
  std::string kind;    ///< "blow-up", "FE solver failure" or "breakdown"
  std::string message; ///< one paragraph: what happened, where, and the likely cause
  std::string remedy;  ///< the failure's own remedy, "" when it names none
};

/// The report of `error`; a blow-up's parameters are spelled by `spell` (the deck's entries).
FailureReport describe_failure(const std::exception& error,
                               const std::function<std::string(const std::string&)>& spell);
} // namespace vulnus::simulator
