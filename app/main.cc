// Entry point of the `vulnus` command: parses the command line and dispatches to the
// subcommands (app/commands.h). Exit status 0 success, 1 run failure, 2 bad usage or deck.
#include "app/command_line.h"
#include "app/commands.h"
#include "analysis/compare_runs.h"
#include "app/point_command.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
  using namespace vulnus::app;
  try
  {
    const CommandLine line = parse_command_line(argc, argv);
    switch (line.command)
    {
    case CommandLine::Command::run:
      return run_command(line);
    case CommandLine::Command::check:
      return check_command(line);
    case CommandLine::Command::print_parameters:
      return print_parameters_command(line);
    case CommandLine::Command::point:
      return point_command(line.arguments);
    case CommandLine::Command::compare:
      return vulnus::analysis::compare_runs(line.arguments[0], line.arguments[1], std::cout, std::cerr);
    case CommandLine::Command::help:
      std::cout << usage_text();
      return 0;
    case CommandLine::Command::version:
      std::cout << version_text();
      return 0;
    }
  }
  catch (const CommandLineError& error)
  {
    std::cerr << "vulnus: error: " << error.what() << "\n\n" << usage_text();
    return 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << "vulnus: error: " << error.what() << '\n';
    return 1;
  }
  return 1;
}
