// Failure reports for the exceptions a step can throw.
#include "simulator/failure_report.h"

#include "core/run_failure.h"

#include <deal.II/base/exceptions.h>

#include <sstream>

namespace vulnus::simulator
{
namespace
{
/// The indented paragraph after `heading` in deal.II's message, joined into one line.
std::string paragraph_after(const std::string& text, const std::string& heading)
{
  const std::size_t start = text.find(heading);
  if (start == std::string::npos)
    return {};
  std::istringstream lines(text.substr(start + heading.size()));
  std::string line, joined;
  std::getline(lines, line); // the rest of the heading's line
  while (std::getline(lines, line))
  {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos)
    {
      if (!joined.empty())
        break;
      continue;
    }
    if (first == 0) // the next heading
      break;
    joined += (joined.empty() ? "" : " ") + line.substr(first);
  }
  return joined;
}

/// deal.II's and Trilinos's words for an iterative linear solve that failed.
bool linear_solver_failed(const std::string& text)
{
  for (const char* word : {"AztecOO", "SolverControl", "NoConvergence", "numerical breakdown",
                           "did not converge", "Iterative method reported"})
    if (text.find(word) != std::string::npos)
      return true;
  return false;
}

const char* const linear_solver_remedy =
  "the implicit far field's linear system could not be solved in this step: its tangent "
  "lost its definiteness, most likely because the step moved the far field's cells far "
  "enough to crush some (an interface guess far off, or strains over a long window); "
  "shorter windows (fewer Hybrid/Substeps, or Far field/Time step), "
  "Far field/Volume averaging = none where the far field's tissue is compressible, or "
  "Far field/Integrator = central difference";
} // namespace

FailureReport describe_failure(const std::exception& error,
                               const std::function<std::string(const std::string&)>& spell)
{
  if (const auto* blow_up = dynamic_cast<const BlowUp*>(&error))
  {
    const RunFailure& f = blow_up->failure();
    return {"blow-up", with_spelled_parameters(describe(f), spell),
            with_spelled_parameters(f.remedy, spell)};
  }
  if (dynamic_cast<const dealii::ExceptionBase*>(&error) != nullptr)
  {
    const std::string text = error.what();
    std::string message = paragraph_after(text, "Additional information:");
    if (message.empty())
      message = "violated condition: " + paragraph_after(text, "The violated condition was:");
    return {"FE solver failure", message, linear_solver_failed(text) ? linear_solver_remedy : ""};
  }
  return {"breakdown", error.what(), {}};
}
} // namespace vulnus::simulator
