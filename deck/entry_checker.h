// Collects a deck's problems, each located at the deck line (or --set) of the entry it names:
// "<where>: <entry>: <problem>; <remedy>".
#pragma once

#include "deck/line_index.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
class Checker
{
public:
  Checker(const EntryLocator& locator) : locator(locator) {}

  /// Report `problem` about `entry` unless `ok`.
  void require(const bool ok, const std::string& entry, const std::string& problem,
               const std::string& remedy)
  {
    if (!ok)
      messages.push_back(locator.where(entry) + ": " + entry + ": " + problem + "; " + remedy);
  }

  /// Same for a problem of several entries: located at the first one the deck sets.
  void require_all(const bool ok, const std::vector<std::string>& entries,
                   const std::string& problem, const std::string& remedy)
  {
    if (ok)
      return;
    std::string where = locator.where(entries.front()), names;
    for (auto e = entries.rbegin(); e != entries.rend(); ++e)
      if (locator.is_set(*e))
        where = locator.where(*e);
    for (const std::string& e : entries)
      names += (names.empty() ? "" : ", ") + e;
    messages.push_back(where + ": " + names + ": " + problem + "; " + remedy);
  }

  std::vector<std::string> messages;

private:
  const EntryLocator& locator;
};
} // namespace vulnus::deck
