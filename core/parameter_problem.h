// A problem a solver library finds in its own parameters, in its own terms: which parameters
// (named as the library's structs name them), what is wrong with them, and the remedy. The
// deck layer maps the parameter names to deck entries and locates the message at their lines,
// so no library needs to know how the deck spells an entry.
#pragma once

#include <string>
#include <vector>

namespace vulnus
{
struct ParameterProblem
{
  std::vector<std::string> parameters; ///< e.g. {"zone_min", "zone_max"}
  std::string problem;                 ///< what is wrong
  std::string remedy;                  ///< how to fix it ("" when the problem says it)
};

/// "problem; remedy" (or the problem alone).
inline std::string describe(const ParameterProblem& p)
{
  return p.remedy.empty() ? p.problem : p.problem + "; " + p.remedy;
}
} // namespace vulnus
