// Entry declaration table and small helpers shared by the deck sections.
#include "deck/deck_entries.h"

#include "deck/line_index.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <regex>

namespace vulnus::deck
{
void EntryTable::enter(const std::string& subsection)
{
  std::vector<std::string>& names = subsection_names[join_path(path)];
  if (std::find(names.begin(), names.end(), subsection) == names.end())
    names.push_back(subsection);
  path.push_back(subsection);
  prm.enter_subsection(subsection);
}

void EntryTable::leave()
{
  path.pop_back();
  prm.leave_subsection();
}

void EntryTable::declare(const std::string& name, const std::string& default_value,
                         const dealii::Patterns::PatternBase& pattern,
                         const std::string& documentation)
{
  const std::string expected = describe_pattern(pattern);
  prm.declare_entry(name, default_value, pattern, documentation + " Allowed: " + expected + ".");
  entries[join_path(path, name)] = EntryInfo{expected, documentation, default_value};
  entry_names[join_path(path)].push_back(name);
}

const EntryInfo* EntryTable::find(const std::string& full_path) const
{
  const auto found = entries.find(full_path);
  return found == entries.end() ? nullptr : &found->second;
}

std::vector<std::string> EntryTable::entries_in(const std::string& section) const
{
  const auto found = entry_names.find(section);
  return found == entry_names.end() ? std::vector<std::string>() : found->second;
}

std::vector<std::string> EntryTable::subsections_in(const std::string& section) const
{
  const auto found = subsection_names.find(section);
  return found == subsection_names.end() ? std::vector<std::string>() : found->second;
}

std::string describe_pattern(const dealii::Patterns::PatternBase& pattern)
{
  using namespace dealii::Patterns;
  if (const auto* list = dynamic_cast<const List*>(&pattern))
    return dynamic_cast<const Double*>(&list->get_base_pattern()) != nullptr
               ? "three numbers `x, y, z`"
               : "a comma-separated list of names (at least one)";
  if (dynamic_cast<const Bool*>(&pattern) != nullptr)
    return "true or false";
  if (dynamic_cast<const Anything*>(&pattern) != nullptr)
    return "any text";

  std::string text = pattern.description(PatternBase::Text);
  while (!text.empty() && (text.back() == '.' || text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  std::smatch match;
  static const std::regex range(
      "^(A floating point number v|An integer n) such that (\\S+) <= [vn] <= (\\S+)");
  if (std::regex_search(text, match, range))
  {
    const std::string kind = match[1].str()[1] == ' ' ? "a number" : "an integer";
    const std::string lower = match[2], upper = match[3];
    const bool no_lower = lower.find("MAX") != std::string::npos || lower == "-2147483648";
    const bool no_upper = upper.find("MAX") != std::string::npos || upper == "2147483647";
    if (no_lower && no_upper)
      return kind;
    if (no_upper)
      return kind + " >= " + lower;
    if (no_lower)
      return kind + " <= " + upper;
    return kind + " in [" + lower + ", " + upper + "]";
  }
  if (text.rfind("Any one of ", 0) == 0)
    return "one of " + text.substr(11);
  if (!text.empty())
    text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

dealii::Patterns::List point_pattern()
{
  return dealii::Patterns::List(dealii::Patterns::Double(), 3, 3, ",");
}

dealii::Patterns::List name_list_pattern()
{
  return dealii::Patterns::List(dealii::Patterns::Anything(), 1,
                                dealii::Patterns::List::max_int_value, ",");
}

std::vector<std::string> split_list(const std::string& text)
{
  std::vector<std::string> items;
  std::size_t begin = 0;
  while (true)
  {
    const std::size_t comma = text.find(',', begin);
    std::string item = text.substr(begin, comma == std::string::npos ? comma : comma - begin);
    const std::size_t first = item.find_first_not_of(" \t");
    const std::size_t last = item.find_last_not_of(" \t");
    items.push_back(first == std::string::npos ? "" : item.substr(first, last - first + 1));
    if (comma == std::string::npos)
      break;
    begin = comma + 1;
  }
  if (items.size() == 1 && items[0].empty())
    items.clear();
  return items;
}

Eigen::Vector3d get_point(const dealii::ParameterHandler& prm, const std::string& name)
{
  const std::vector<std::string> items = split_list(prm.get(name));
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  for (unsigned int d = 0; d < 3 && d < items.size(); ++d)
    point[d] = std::strtod(items[d].c_str(), nullptr);
  return point;
}

std::string format_number(const double value)
{
  char text[40];
  for (int precision = 6; precision <= 17; ++precision)
  {
    std::snprintf(text, sizeof(text), "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value)
      break;
  }
  return text;
}

std::string format_point(const Eigen::Vector3d& point)
{
  return format_number(point[0]) + ", " + format_number(point[1]) + ", " + format_number(point[2]);
}

unsigned int edit_distance(const std::string& a, const std::string& b)
{
  std::vector<unsigned int> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    previous[j] = static_cast<unsigned int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    current[0] = static_cast<unsigned int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      current[j] =
          std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::string closest_name(const std::string& name, const std::vector<std::string>& candidates)
{
  std::string best;
  unsigned int best_distance = 0;
  for (const std::string& candidate : candidates)
  {
    const unsigned int distance = edit_distance(name, candidate);
    if (best.empty() || distance < best_distance)
    {
      best = candidate;
      best_distance = distance;
    }
  }
  // Accept up to a third of the length in edits (at least 2).
  const std::size_t allowed = std::max<std::size_t>(2, name.size() / 3);
  return best_distance <= allowed ? best : std::string();
}
} // namespace vulnus::deck
