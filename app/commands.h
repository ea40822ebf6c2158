// The subcommands of `vulnus` behind main(): each returns the process exit status
// (0 success, 1 failure during a run, 2 bad deck or command line).
#pragma once

#include "app/command_line.h"

namespace vulnus::app
{
/// `vulnus run`: read and check the deck (nothing is written if that fails), create the run
/// directory, write deck_used.prm, run the simulation.
int run_command(const CommandLine& line);

/// `vulnus check`: read and check the deck, print "deck OK" or the errors.
int check_command(const CommandLine& line);

/// `vulnus --print-parameters`.
int print_parameters_command(const CommandLine& line);
} // namespace vulnus::app
