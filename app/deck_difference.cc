// Entry-by-entry comparison of resolved PRM decks: `subsection` nesting gives the path,
// `set Entry = value` the value; comments are dropped.
#include "app/deck_difference.h"

#include <map>
#include <sstream>

namespace vulnus::app
{
namespace
{
std::string trimmed(const std::string& text)
{
  const std::size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos)
    return "";
  const std::size_t end = text.find_last_not_of(" \t\r");
  return text.substr(begin, end - begin + 1);
}

std::map<std::string, std::string> entries_of(const std::string& deck)
{
  std::map<std::string, std::string> entries;
  std::vector<std::string> sections;
  std::istringstream in(deck);
  std::string line;
  while (std::getline(in, line))
  {
    line = trimmed(line.substr(0, line.find('#')));
    if (line.rfind("subsection ", 0) == 0)
      sections.push_back(trimmed(line.substr(11)));
    else if (line == "end" && !sections.empty())
      sections.pop_back();
    else if (line.rfind("set ", 0) == 0)
    {
      const std::size_t equals = line.find('=');
      if (equals == std::string::npos)
        continue;
      std::string path;
      for (const std::string& section : sections)
        path += section + "/";
      entries[path + trimmed(line.substr(4, equals - 4))] = trimmed(line.substr(equals + 1));
    }
  }
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
                                  const std::vector<std::string>& ignored)
{
  const std::map<std::string, std::string> before = entries_of(checkpoint_deck);
  const std::map<std::string, std::string> now = entries_of(deck);
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
    if (!is_ignored(path, ignored) && before.count(path) == 0)
      return path + ": absent from the checkpoint, '" + value + "' in the deck";
  return "";
}
} // namespace vulnus::app
