// Entry-by-entry comparison of resolved PRM decks, read through the deck's statement index.
#include "deck/deck_difference.h"

#include "deck/line_index.h"

#include <map>

namespace vulnus::deck
{
namespace
{
std::map<std::string, std::string> entries_of(const std::string& deck)
{
  std::map<std::string, std::string> entries;
  const LineIndex index(deck, "deck");
  for (const DeckStatement& statement : index.statements())
    if (statement.kind == DeckStatement::Kind::set && statement.has_equals)
      entries[statement.full_path()] = statement.value;
  return entries;
}

bool is_ignored(const std::string& path, const std::vector<std::string>& ignored)
{
  for (const std::string& prefix : ignored)
    if (path.rfind(prefix, 0) == 0)
      return true;
  return false;
}
} // namespace

std::string first_deck_difference(const std::string& checkpoint_deck, const std::string& deck,
                                  const std::vector<std::string>& ignored,
                                  const std::string& defaults,
                                  std::vector<std::string>& taken_at_default)
{
  const std::map<std::string, std::string> before = entries_of(checkpoint_deck);
  const std::map<std::string, std::string> now = entries_of(deck);
  const std::map<std::string, std::string> default_value = entries_of(defaults);
  taken_at_default.clear();
  for (const auto& [path, value] : before)
  {
    if (is_ignored(path, ignored))
      continue;
    const auto found = now.find(path);
    if (found == now.end())
      return path + ": '" + value + "' in the checkpoint, absent from the deck";
    if (found->second != value)
      return path + ": '" + value + "' in the checkpoint, '" + found->second + "' in the deck";
  }
  for (const auto& [path, value] : now)
  {
    if (is_ignored(path, ignored) || before.count(path) > 0)
      continue;
    const auto preset = default_value.find(path);
    if (preset == default_value.end() || preset->second != value)
      return path + ": absent from the checkpoint, '" + value + "' in the deck" +
             (preset == default_value.end() ? std::string()
                                            : " (its default is '" +
                                                preset->second + "')");
    taken_at_default.push_back(path);
  }
  return "";
}
} // namespace vulnus::deck
