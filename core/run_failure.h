// A failure a solver detects during a run, in its own terms: what happened and where, the
// likely cause, and a remedy that cites the solver's parameters as {name} (the names of its
// structs' members). The front end that runs it spells each {name} its own way (the deck entry),
// and falls back on the run type's generic remedy only when the failure names none.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

namespace vulnus
{
struct RunFailure
{
  std::string problem; ///< what happened and where: step, time, point, body, position
  std::string cause;   ///< the likely cause, "" when the solver cannot tell
  std::string remedy;  ///< cites parameters as {name}; "" leaves the run type's generic remedy
  bool empty() const { return problem.empty(); }
};

/// `text` with every {name} replaced by spell(name).
inline std::string with_spelled_parameters(const std::string& text,
                                           const std::function<std::string(const std::string&)>& spell)
{
  std::string out;
  std::size_t at = 0;
  while (at < text.size())
  {
    const std::size_t open = text.find('{', at);
    const std::size_t close = open == std::string::npos ? open : text.find('}', open);
    if (close == std::string::npos)
    {
      out += text.substr(at);
      break;
    }
    out += text.substr(at, open - at) + spell(text.substr(open + 1, close - open - 1));
    at = close + 1;
  }
  return out;
}

/// "problem; likely cause: cause" (the remedy is reported on its own).
inline std::string describe(const RunFailure& f)
{
  return f.cause.empty() ? f.problem : f.problem + "; likely cause: " + f.cause;
}

/// A numerical blow-up or a state the run cannot go on from; what() holds the problem, the
/// cause and the remedy with the solver's own parameter names.
class BlowUp : public std::runtime_error
{
public:
  explicit BlowUp(RunFailure f)
    : std::runtime_error(with_spelled_parameters(
        f.remedy.empty() ? describe(f) : describe(f) + "; remedy: " + f.remedy,
        [](const std::string& name) { return name; })),
      failure_(std::move(f))
  {
  }
  explicit BlowUp(const std::string& problem) : BlowUp(RunFailure{problem, {}, {}}) {}
  const RunFailure& failure() const { return failure_; }

private:
  RunFailure failure_;
};
} // namespace vulnus
