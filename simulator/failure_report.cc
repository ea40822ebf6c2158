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
    return {"FE solver failure", message, {}};
  }
  return {"breakdown", error.what(), {}};
}
} // namespace vulnus::simulator
