// The deck reading framework: two-pass ParameterHandler parsing, --set overrides, deal.II
// exceptions turned into one clear message each, cross-entry checks.
#include "deck/deck_reader.h"

#include "deck/deck_checks.h"
#include "deck/axisymmetric_checks.h"
#include "deck/graded_grid_checks.h"
#include "deck/point_splitting_checks.h"
#include "deck/symmetry_checks.h"
#include "deck/method_checks.h"
#include "deck/deck_entries.h"
#include "deck/deck_sections.h"
#include "deck/line_index.h"
#include "deck/version.h"
#include "materials/material_registry.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>

namespace vulnus::deck
{
namespace
{
std::string join(const std::vector<std::string>& items, const std::string& separator = ", ")
{
  std::string joined;
  for (const std::string& item : items)
    joined += (joined.empty() ? "" : separator) + item;
  return joined;
}

std::string trim(const std::string& s)
{
  const std::size_t begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos)
    return "";
  return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

/// One input applied to the handler: the deck, or one override turned into deck text.
struct Source
{
  std::string text;
  std::string origin; ///< file name, or the override as the user wrote it
  bool is_override = false;
  std::unique_ptr<LineIndex> index;

  Source(std::string text_, std::string origin_, const bool is_override_)
      : text(std::move(text_)), origin(std::move(origin_)), is_override(is_override_),
        index(std::make_unique<LineIndex>(text, origin))
  {
  }

  std::string location(const unsigned int line) const
  {
    return is_override || line == 0 ? origin : origin + ":" + std::to_string(line);
  }
};

std::string read_deck_file(const std::string& path)
{
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
    throw DeckError({path + ": cannot read the deck (not a regular file); give the path of a "
                            ".prm file"});
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw DeckError({path + ": cannot read the deck (" + std::strerror(errno) +
                     "); check the path, or write a deck with `vulnus --print-parameters " + path +
                     "`"});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw DeckError({path + ": cannot read the deck (read error); check the file"});
  return text.str();
}

/// `Section/Sub/Entry=value` -> deck text.
Source override_source(const DeckOverride& override_)
{
  const std::string& assignment = override_.assignment;
  const std::size_t equals = assignment.find('=');
  const auto fail = [&](const std::string& problem)
  {
    throw DeckError({override_.origin + ": " + problem +
                     "; write it as 'Section/Entry=value', e.g. --set 'Grid/Cell size=5e-4'"});
  };
  if (equals == std::string::npos)
    fail("no '=' in the override");
  const std::string value = trim(assignment.substr(equals + 1));
  if (value.find_first_of("\n\r") != std::string::npos)
    fail("the value contains a line break");
  std::vector<std::string> path;
  std::stringstream names(assignment.substr(0, equals));
  for (std::string part; std::getline(names, part, '/');)
    path.push_back(trim(part));
  if (path.size() < 2 || std::find(path.begin(), path.end(), "") != path.end())
    fail("'" + assignment.substr(0, equals) + "' is not a path Section/.../Entry");

  std::string text;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    text += "subsection " + path[i] + "\n";
  text += "set " + path.back() + " = " + value + "\n";
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    text += "end\n";
  return Source(text, override_.origin, true);
}

/// Line number a deal.II parse exception refers to (0 if none).
unsigned int line_of(const std::string& info)
{
  std::smatch match;
  if (std::regex_search(info, match, std::regex("Line <([0-9]+)>")))
    return static_cast<unsigned int>(std::stoul(match[1]));
  return 0;
}

std::string unknown_subsection_message(const DeckStatement& statement, const EntryTable& table,
                                       const std::vector<std::string>& material_names,
                                       const std::vector<std::string>& body_names)
{
  const std::string& name = statement.name;
  if (statement.path.empty() && name.rfind("Material ", 0) == 0)
    return "there is no material named '" + name.substr(9) + "' in Scene/Materials (" +
           join(material_names) + "); add the name there, or correct it";
  if (statement.path.empty() && name.rfind("Body ", 0) == 0)
    return "there is no body named '" + name.substr(5) + "' in Scene/Bodies (" + join(body_names) +
           "); add the name there, or correct it";
  const std::string parent = join_path(statement.path);
  const std::vector<std::string> known = table.subsections_in(parent);
  const std::string where = parent.empty() ? "at the top level" : "in '" + parent + "'";
  const std::string guess = closest_name(name, known);
  return "no subsection '" + name + "' " + where + "; " +
         (guess.empty() ? "" : "did you mean '" + guess + "'? ") + "the subsections " + where +
         " are: " + (known.empty() ? "none" : join(known));
}

/// Turn a deal.II parse exception into one message naming the entry, its line and the fix.
std::string explain(const dealii::ExceptionBase& exception, const Source& source,
                    const EntryTable& table, const std::vector<std::string>& material_names,
                    const std::vector<std::string>& body_names)
{
  std::ostringstream info_stream;
  exception.print_info(info_stream);
  const std::string info = info_stream.str();

  if (dynamic_cast<const dealii::ParameterHandler::ExcUnbalancedSubsections*>(&exception))
  {
    const std::vector<const DeckStatement*> open = source.index->unclosed_subsections();
    if (!open.empty())
      return source.location(open.back()->first_line) + ": subsection '" +
             open.back()->full_path() + "' is never closed; add 'end' after its last entry";
  }

  const unsigned int line = line_of(info);
  const DeckStatement* statement = source.index->statement_at(line);
  const std::string where = source.location(line) + ": ";
  if (statement != nullptr)
    switch (statement->kind)
    {
    case DeckStatement::Kind::set:
    {
      const std::string path = statement->full_path();
      if (!statement->has_equals)
        return where + "'set " + statement->name + "' has no '='; write 'set " + statement->name +
               " = VALUE'";
      if (const EntryInfo* entry = table.find(path))
        return where + path + " = '" + statement->value + "' is not valid; expected " +
               entry->expected + " (" + entry->documentation + ")";
      const std::string section = join_path(statement->path);
      if (section.empty())
        return where + "'set " + statement->name +
               "' outside any subsection; every entry belongs to a subsection such as Grid";
      const std::vector<std::string> known = table.entries_in(section);
      const std::string guess = closest_name(statement->name, known);
      return where + path + ": no such entry in subsection '" + section + "'; " +
             (guess.empty() ? "" : "did you mean '" + guess + "'? ") +
             "the entries there are: " + (known.empty() ? "none" : join(known));
    }
    case DeckStatement::Kind::subsection:
      return where + unknown_subsection_message(*statement, table, material_names, body_names);
    case DeckStatement::Kind::end:
      return where + "'end' without a matching 'subsection'; remove it";
    case DeckStatement::Kind::include:
      return where + "cannot open the included file '" + statement->name +
             "'; check its path (relative to the working directory)";
    case DeckStatement::Kind::other:
      return where + "cannot read '" + statement->name +
             "'; each line is 'subsection NAME', 'set ENTRY = VALUE', 'end', "
             "'include FILE' or a # comment";
    case DeckStatement::Kind::blank:
      break;
    }
  // Not a line we recognise: pass deal.II's own text on, on one line.
  std::string text = info;
  std::replace(text.begin(), text.end(), '\n', ' ');
  return source.origin + ": " + std::regex_replace(trim(text), std::regex(" +"), " ");
}

/// deal.II does not check a value holding '{' or '}' against its pattern (the braces mark
/// variants for its parameter loops), so the value would fail only later, when read.
void refuse_braces(const Source& source, const EntryTable& table)
{
  for (const DeckStatement& statement : source.index->statements())
  {
    if (statement.kind != DeckStatement::Kind::set ||
        statement.value.find_first_of("{}") == std::string::npos)
      continue;
    const std::string path = statement.full_path();
    const EntryInfo* entry = table.find(path);
    throw DeckError({source.location(statement.first_line) + ": " + path + " = '" +
                     statement.value + "' is not valid; " +
                     (entry ? "expected " + entry->expected + " (" + entry->documentation + ")"
                            : std::string("'{' and '}' are not allowed in values"))});
  }
}

/// Parse one source, turning deal.II's exceptions into DeckError.
void parse(dealii::ParameterHandler& prm, const Source& source, const bool skip_undefined,
           const EntryTable& table, const std::vector<std::string>& material_names,
           const std::vector<std::string>& body_names)
{
  refuse_braces(source, table);
  try
  {
    std::istringstream in(source.text);
    prm.parse_input(in, source.origin, "", skip_undefined);
  }
  catch (const dealii::ExceptionBase& exception)
  {
    throw DeckError({explain(exception, source, table, material_names, body_names)});
  }
}

void check_names(const std::vector<std::string>& names, const std::string& entry,
                 const EntryLocator& locator)
{
  std::set<std::string> seen;
  for (const std::string& name : names)
  {
    std::string problem;
    if (name.empty())
      problem = "an empty name in the list";
    else if (name.find_first_of("/#\\") != std::string::npos)
      problem = "the name '" + name + "' contains '/', '#' or '\\'";
    else if (!seen.insert(name).second)
      problem = "the name '" + name + "' appears twice";
    if (!problem.empty())
      throw DeckError({locator.where(entry) + ": " + entry + ": " + problem +
                       "; give distinct names separated by commas"});
  }
}

void declare_all(EntryTable& table, const SceneNames& names)
{
  declare_scene_section(table);
  declare_material_sections(table, names.materials);
  declare_body_sections(table, names.bodies);
  declare_grid_section(table);
  declare_contact_section(table);
  declare_time_section(table);
  declare_output_section(table);
  declare_run_section(table);
  declare_far_field_section(table);
  declare_hybrid_section(table);
}

std::string listing_header()
{
  std::string header =
      "# vulnus " VULNUS_VERSION
      " deck (deal.II ParameterHandler format). Units SI: m, kg, s, Pa.\n"
      "# Every entry is listed with its documentation and allowed values; an entry whose value\n"
      "# differs from its default ends in `# default: ...`. Unknown entries are errors.\n"
      "# Material models (entry Model of `subsection Material <name>`):\n";
  for (const std::string& model : materials::registered_model_names())
  {
    std::string line = "#   " + model + ": ";
    std::istringstream words(materials::model_documentation(model));
    for (std::string word; words >> word;)
    {
      if (line.size() + word.size() + 1 > 92)
      {
        header += line + "\n";
        line = "#     ";
      }
      line += (line.back() == ' ' ? "" : " ") + word;
    }
    header += line + "\n";
  }
  return header + "\n";
}

std::string print(const dealii::ParameterHandler& prm)
{
  std::ostringstream out;
  out << listing_header();
  prm.print_parameters(
      out, dealii::ParameterHandler::OutputStyle(dealii::ParameterHandler::PRM |
                                                 dealii::ParameterHandler::KeepDeclarationOrder));
  return out.str();
}

/// The two passes; returns the handler (entries parsed) and the sources applied.
struct ParsedDeck
{
  dealii::ParameterHandler prm;
  std::unique_ptr<EntryTable> table;
  SceneNames names;
  std::vector<Source> sources;
};

void parse_deck(ParsedDeck& deck)
{
  std::vector<const LineIndex*> indices;
  for (const Source& source : deck.sources)
    indices.push_back(source.index.get());
  const EntryLocator locator(indices);

  // Pass 1: learn the names of the materials and bodies.
  {
    dealii::ParameterHandler names_prm;
    EntryTable names_table(names_prm);
    declare_scene_section(names_table);
    for (const Source& source : deck.sources)
      parse(names_prm, source, true, names_table, {}, {});
    deck.names = parse_scene_section(names_prm);
    check_names(deck.names.materials, "Scene/Materials", locator);
    check_names(deck.names.bodies, "Scene/Bodies", locator);
  }
  // Pass 2: every entry, strictly.
  deck.table = std::make_unique<EntryTable>(deck.prm);
  declare_all(*deck.table, deck.names);
  for (const Source& source : deck.sources)
    parse(deck.prm, source, false, *deck.table, deck.names.materials, deck.names.bodies);
}

void add_sources(ParsedDeck& deck, const std::string& text, const std::string& source_name,
                 const std::vector<DeckOverride>& overrides)
{
  deck.sources.emplace_back(text, source_name, false);
  for (const DeckOverride& override_ : overrides)
    deck.sources.push_back(override_source(override_));
}
} // namespace

DeckError::DeckError(const std::vector<std::string>& messages)
    : std::runtime_error(join(messages, "\n")), message_list(messages)
{
}

RunParameters read_run_parameters(const std::string& deck_path,
                                  const std::vector<DeckOverride>& overrides)
{
  RunParameters parameters =
      read_run_parameters_from_text(read_deck_file(deck_path), deck_path, overrides);
  parameters.deck_path = deck_path;
  return parameters;
}

RunParameters read_run_parameters_from_text(const std::string& text, const std::string& source_name,
                                            const std::vector<DeckOverride>& overrides)
{
  ParsedDeck deck;
  add_sources(deck, text, source_name, overrides);
  parse_deck(deck);

  RunParameters parameters;
  dealii::ParameterHandler& prm = deck.prm;
  parameters.scene.materials = parse_material_sections(prm, deck.names.materials);
  parameters.scene.bodies = parse_body_sections(prm, deck.names.bodies);
  parse_grid_section(prm, parameters.scene);
  parse_contact_section(prm, parameters.scene.contact);
  parse_time_section(prm, parameters.scene, parameters.energy_guard);
  parse_output_section(prm, parameters.output);
  parse_run_section(prm, parameters.scene);
  parse_far_field_section(prm, parameters);
  parse_hybrid_section(prm, parameters.hybrid);
  parameters.resolved_deck = print(prm);

  std::vector<const LineIndex*> indices;
  for (const Source& source : deck.sources)
    indices.push_back(source.index.get());
  std::vector<std::string> problems = check_run_parameters(parameters, EntryLocator(indices));
  for (const std::string& p : check_method(parameters, EntryLocator(indices)))
    problems.push_back(p);
  for (const std::string& p : check_axisymmetric(parameters, EntryLocator(indices)))
    problems.push_back(p);
  for (const std::string& p : check_symmetry(parameters, EntryLocator(indices)))
    problems.push_back(p);
  for (const std::string& p : check_graded_grid(parameters, EntryLocator(indices)))
    problems.push_back(p);
  for (const std::string& p : check_point_splitting(parameters, EntryLocator(indices)))
    problems.push_back(p);
  if (!problems.empty())
    throw DeckError(problems);
  return parameters;
}

std::string parameter_listing(const std::string& deck_path,
                              const std::vector<DeckOverride>& overrides)
{
  ParsedDeck deck;
  if (deck_path.empty())
    add_sources(deck, "", "(defaults)", overrides);
  else
    add_sources(deck, read_deck_file(deck_path), deck_path, overrides);
  parse_deck(deck);
  return print(deck.prm);
}
} // namespace vulnus::deck
