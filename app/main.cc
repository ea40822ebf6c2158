// Entry point of the `vulnus` command: parses the command line and dispatches to the
// subcommands (app/commands.h). Exit status 0 success, 1 run failure, 2 bad usage or deck.
#include "app/command_line.h"
#include "app/commands.h"

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
      // LEAD: wire `vulnus point` here.
      std::cerr << "vulnus: error: 'vulnus point' is not available yet\n";
      return 2;
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
