// Named columns of a CSV file as numbers.
#include "io/csv_columns.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vulnus::io
{
namespace
{
std::vector<std::string> split(const std::string& line)
{
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ','))
    fields.push_back(field);
  return fields;
}
} // namespace

std::vector<std::vector<double>> read_csv_columns(const std::string& path,
                                                  const std::vector<std::string>& names)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line))
    throw std::runtime_error(path + ": cannot read its header row");
  const std::vector<std::string> header = split(line);
  std::vector<std::size_t> index;
  for (const std::string& name : names)
  {
    const auto found = std::find(header.begin(), header.end(), name);
    if (found == header.end())
      throw std::runtime_error(path + ": no column \"" + name + "\" in its header");
    index.push_back(static_cast<std::size_t>(found - header.begin()));
  }
  std::vector<std::vector<double>> columns(names.size());
  for (std::size_t line_number = 2; std::getline(in, line); ++line_number)
  {
    if (line.empty())
      continue;
    const std::vector<std::string> fields = split(line);
    for (std::size_t k = 0; k < names.size(); ++k)
    {
      const char* text = index[k] < fields.size() ? fields[index[k]].c_str() : "";
      char* end = nullptr;
      const double value = std::strtod(text, &end);
      if (end == text || *end != '\0')
        throw std::runtime_error(path + " line " + std::to_string(line_number) + ": column \"" +
                                 names[k] + "\" is not a number");
      columns[k].push_back(value);
    }
  }
  return columns;
}
} // namespace vulnus::io
