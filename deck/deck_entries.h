// Declaring deck entries: a thin layer over deal.II's ParameterHandler that also records, per
// entry, its full path, pattern description and documentation, so that deck errors can say
// what was expected and suggest the entry a misspelling meant. Included by deck files only.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace vulnus::deck
{
struct EntryInfo
{
  std::string expected;      ///< readable pattern description
  std::string documentation; ///< as declared (without the appended allowed values)
  std::string default_value;
};

/// Declares entries in a ParameterHandler, tracking the current subsection path.
class EntryTable
{
public:
  explicit EntryTable(dealii::ParameterHandler& prm) : prm(prm) {}

  void enter(const std::string& subsection);
  void leave();

  /// Declare `name` in the current subsection. `documentation` states the symbol and units;
  /// the allowed values are appended to it in the printed deck.
  void declare(const std::string& name, const std::string& default_value,
               const dealii::Patterns::PatternBase& pattern, const std::string& documentation);

  const EntryInfo* find(const std::string& full_path) const;
  /// Entry names declared directly in subsection `path` ("" for the top level).
  std::vector<std::string> entries_in(const std::string& path) const;
  /// Subsection names declared directly in `path`.
  std::vector<std::string> subsections_in(const std::string& path) const;

private:
  dealii::ParameterHandler& prm;
  std::vector<std::string> path;
  std::map<std::string, EntryInfo> entries;
  std::map<std::string, std::vector<std::string>> entry_names;
  std::map<std::string, std::vector<std::string>> subsection_names;
};

/// Readable description of a pattern ("a floating point number v such that 0 <= v", ...).
std::string describe_pattern(const dealii::Patterns::PatternBase& pattern);

/// Pattern of a point or vector written `x, y, z`.
dealii::Patterns::List point_pattern();
/// Pattern of a list of names separated by commas, at least one.
dealii::Patterns::List name_list_pattern();

/// `x, y, z` -> vector (the pattern has been checked already).
Eigen::Vector3d get_point(const dealii::ParameterHandler& prm, const std::string& name);
/// Vector -> `x, y, z` with round-trip precision.
std::string format_point(const Eigen::Vector3d& point);
/// Number -> shortest text that reads back to the same double.
std::string format_number(double value);

/// Split a comma separated list, trimming each item.
std::vector<std::string> split_list(const std::string& text);

/// Levenshtein distance, for "did you mean" suggestions (case-insensitive).
unsigned int edit_distance(const std::string& a, const std::string& b);
/// The candidate closest to `name`, if it is close enough to be a likely misspelling.
std::string closest_name(const std::string& name, const std::vector<std::string>& candidates);
} // namespace vulnus::deck
