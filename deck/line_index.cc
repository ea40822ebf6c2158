// Statement index of a PRM deck, following deal.II's ParameterHandler::scan_line rules.
#include "deck/line_index.h"

#include <sstream>

namespace vulnus::deck
{
namespace
{
std::string trim(const std::string& s)
{
  const std::size_t begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos)
    return "";
  const std::size_t end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

/// Drop a comment (an unescaped '#') as deal.II does.
std::string strip_comment(const std::string& line)
{
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '#' && (i == 0 || line[i - 1] != '\\'))
      return line.substr(0, i);
  return line;
}

bool starts_with_keyword(const std::string& line, const std::string& lower, std::string& rest)
{
  std::string upper = lower;
  for (char& c : upper)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const std::string& keyword : {lower + " ", upper + " ", lower + "\t", upper + "\t"})
    if (line.compare(0, keyword.size(), keyword) == 0)
    {
      rest = trim(line.substr(keyword.size()));
      return true;
    }
  return false;
}
} // namespace

std::string join_path(const std::vector<std::string>& path, const std::string& last)
{
  std::string joined;
  for (const std::string& part : path)
    joined += (joined.empty() ? "" : "/") + part;
  if (!last.empty())
    joined += (joined.empty() ? "" : "/") + last;
  return joined;
}

std::string DeckStatement::full_path() const
{
  return join_path(path, name);
}

LineIndex::LineIndex(const std::string& text, const std::string& source) : source_name(source)
{
  std::istringstream in(text);
  std::vector<std::string> path;
  std::string physical;
  unsigned int line_number = 0;
  while (std::getline(in, physical))
  {
    ++line_number;
    DeckStatement statement;
    statement.first_line = line_number;
    std::string line = physical;
    // A trailing backslash continues the line (deal.II joins before stripping comments).
    while (!trim(line).empty() && trim(line).back() == '\\' && std::getline(in, physical))
    {
      ++line_number;
      const std::string head = trim(line);
      line = head.substr(0, head.size() - 1) + physical;
    }
    statement.last_line = line_number;
    line = trim(strip_comment(line));
    statement.path = path;

    std::string rest;
    if (line.empty())
      statement.kind = DeckStatement::Kind::blank;
    else if (starts_with_keyword(line, "set", rest))
    {
      statement.kind = DeckStatement::Kind::set;
      const std::size_t equals = rest.find('=');
      statement.has_equals = equals != std::string::npos;
      statement.name = trim(rest.substr(0, equals));
      if (statement.has_equals)
        statement.value = trim(rest.substr(equals + 1));
    }
    else if (starts_with_keyword(line, "subsection", rest))
    {
      statement.kind = DeckStatement::Kind::subsection;
      statement.name = rest;
      path.push_back(rest);
    }
    else if (line == "end" || line == "END")
    {
      statement.kind = DeckStatement::Kind::end;
      if (!path.empty())
      {
        statement.name = path.back();
        path.pop_back();
        statement.path = path;
      }
    }
    else if (starts_with_keyword(line, "include", rest))
    {
      statement.kind = DeckStatement::Kind::include;
      statement.name = rest;
    }
    else
    {
      statement.kind = DeckStatement::Kind::other;
      statement.name = line;
    }
    statement_list.push_back(statement);
  }
}

const DeckStatement* LineIndex::statement_at(const unsigned int line) const
{
  for (const DeckStatement& statement : statement_list)
    if (statement.first_line <= line && line <= statement.last_line)
      return &statement;
  return nullptr;
}

const DeckStatement* LineIndex::last_set(const std::string& path) const
{
  const DeckStatement* found = nullptr;
  for (const DeckStatement& statement : statement_list)
    if (statement.kind == DeckStatement::Kind::set && statement.full_path() == path)
      found = &statement;
  return found;
}

std::vector<const DeckStatement*> LineIndex::unclosed_subsections() const
{
  std::vector<const DeckStatement*> open;
  for (const DeckStatement& statement : statement_list)
    if (statement.kind == DeckStatement::Kind::subsection)
      open.push_back(&statement);
    else if (statement.kind == DeckStatement::Kind::end && !open.empty())
      open.pop_back();
  return open;
}

EntryLocator::EntryLocator(std::vector<const LineIndex*> indices) : indices(std::move(indices)) {}

std::string EntryLocator::where(const std::string& path) const
{
  for (auto index = indices.rbegin(); index != indices.rend(); ++index)
    if (const DeckStatement* statement = (*index)->last_set(path))
    {
      // A --set source is one line: name it without a line number.
      if ((*index)->source().rfind("--", 0) == 0)
        return (*index)->source();
      return (*index)->source() + ":" + std::to_string(statement->first_line);
    }
  return indices.empty() ? std::string("(default value)")
                         : indices.front()->source() + " (default value)";
}

bool EntryLocator::is_set(const std::string& path) const
{
  for (const LineIndex* index : indices)
    if (index->last_set(path) != nullptr)
      return true;
  return false;
}
} // namespace vulnus::deck
