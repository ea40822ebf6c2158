// The command line of `vulnus`: subcommands and options parsed into a plain struct, and the
// usage text. No deal.II here.
#pragma once

#include "deck/deck_reader.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace vulnus::app
{
/// A command line that cannot be used; reported with the usage and exit status 2.
class CommandLineError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct CommandLine
{
  enum class Command
  {
    run,              ///< vulnus run DECK [--output DIR | --restart DIR] [--set ...] [--threads N]
    check,            ///< vulnus check DECK [--set ...]: validate only
    print_parameters, ///< vulnus --print-parameters [FILE] [--deck DECK] [--set ...]
    point,            ///< vulnus point ... (arguments in `arguments`)
    compare,          ///< vulnus compare RUN_A RUN_B (the two in `arguments`)
    help,
    version
  };

  Command command = Command::help;
  std::string deck;        ///< run, check; print_parameters with --deck
  std::string output_file; ///< print_parameters: FILE ("" = stdout)
  /// --set overrides, then --output and --threads as overrides of Output/Directory and
  /// Run/Threads, in that order.
  std::vector<deck::DeckOverride> overrides;
  std::vector<std::string> arguments; ///< point: everything after it; compare: the two runs
  /// run --restart RUN_DIR: continue from the newest complete checkpoint there ("" = fresh run).
  std::string restart_directory;
};

/// Throws CommandLineError for an unknown subcommand or option, a missing argument, or
/// `--restart` together with `--output`.
CommandLine parse_command_line(int argc, const char* const* argv);

std::string usage_text();
std::string version_text();
} // namespace vulnus::app
