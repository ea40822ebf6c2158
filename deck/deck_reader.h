// Reading a deck into RunParameters: deal.II ParameterHandler in two passes (names of the
// materials and bodies first, then every entry strictly), `--set` overrides applied after the
// deck and validated like deck lines, cross-entry checks, and one clear message per error
// (entry path, file and line, what was expected). No deal.II in this header.
#pragma once

#include "deck/run_parameters.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace vulnus::deck
{
/// A deck that cannot be used: each message names the entry, where it was set and what to
/// do. Reported with exit status 2 before any work starts.
class DeckError : public std::runtime_error
{
public:
  explicit DeckError(const std::vector<std::string>& messages);
  const std::vector<std::string>& messages() const { return message_list; }

private:
  std::vector<std::string> message_list;
};

/// One `Section/Subsection/Entry=value` override and how the user wrote it (for messages),
/// e.g. {"Grid/Cell size=5e-4", "--set 'Grid/Cell size=5e-4'"}.
struct DeckOverride
{
  std::string assignment;
  std::string origin;
};

/// Read the deck at `deck_path`, apply the overrides in order, check. Throws DeckError.
RunParameters read_run_parameters(const std::string& deck_path,
                                  const std::vector<DeckOverride>& overrides = {});

/// Same for deck text; `source_name` names it in messages.
RunParameters read_run_parameters_from_text(const std::string& text, const std::string& source_name,
                                            const std::vector<DeckOverride>& overrides = {});

/// Every parameter with its documentation, allowed values and default, as a valid deck: the
/// defaults, or the deck at `deck_path` (if not empty) with the overrides applied. Throws
/// DeckError for a bad deck or override; cross-entry checks are not applied.
std::string parameter_listing(const std::string& deck_path = "",
                              const std::vector<DeckOverride>& overrides = {});
} // namespace vulnus::deck
