// A small index of the statements of a deck (`set`, `subsection`, `end`, ...) with their line
// numbers, so that errors can name an entry's full path (`Section/Subsection/Entry`) and the
// line where it was set. Mirrors deal.II's PRM syntax: `#` comments, `\` line continuation.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace vulnus::deck
{
struct DeckStatement
{
  enum class Kind
  {
    blank, ///< empty or comment only
    set,
    subsection,
    end,
    include,
    other ///< anything deal.II cannot parse
  };

  Kind kind = Kind::blank;
  unsigned int first_line = 0;   ///< 1-based
  unsigned int last_line = 0;    ///< differs from first_line for continued lines
  std::vector<std::string> path; ///< enclosing subsections
  std::string name;              ///< entry or subsection name
  std::string value;             ///< value of a `set`
  bool has_equals = false;

  /// `Section/Subsection/Entry` (or the subsection's own path).
  std::string full_path() const;
};

class LineIndex
{
public:
  /// Index `text`; `source` names it in messages (a file name, or "--set '...'").
  LineIndex(const std::string& text, const std::string& source);

  const std::string& source() const { return source_name; }
  const std::vector<DeckStatement>& statements() const { return statement_list; }

  /// The statement covering 1-based `line`, if any.
  const DeckStatement* statement_at(unsigned int line) const;

  /// The last `set` of the entry with full path `path`, if any.
  const DeckStatement* last_set(const std::string& path) const;

  /// `subsection` statements still open at the end of the text (unbalanced).
  std::vector<const DeckStatement*> unclosed_subsections() const;

private:
  std::string source_name;
  std::vector<DeckStatement> statement_list;
};

/// Joins path components with '/'.
std::string join_path(const std::vector<std::string>& path, const std::string& last = "");

/// Where an entry got its value: the last of the sources (deck, then each --set) that set it.
class EntryLocator
{
public:
  /// `indices` in the order they were applied; later ones win.
  explicit EntryLocator(std::vector<const LineIndex*> indices);

  /// "deck.prm:12", "--set 'Grid/Cell size=1e-3'", or "deck.prm (default value)".
  std::string where(const std::string& path) const;
  /// Whether a deck line or a --set gave the entry its value (not its default).
  bool is_set(const std::string& path) const;

private:
  std::vector<const LineIndex*> indices;
};
} // namespace vulnus::deck
