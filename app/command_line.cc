// Parsing the command line of `vulnus`.
#include "app/command_line.h"

#include "deck/version.h"

namespace vulnus::app
{
namespace
{
/// Splits `--name=value` into name and value.
bool split_option(const std::string& argument, std::string& name, std::string& value)
{
  const std::size_t equals = argument.find('=');
  if (argument.rfind("--", 0) != 0 || equals == std::string::npos)
    return false;
  name = argument.substr(0, equals);
  value = argument.substr(equals + 1);
  return true;
}

/// Reads the options shared by `run`, `check` and `--print-parameters`.
class OptionReader
{
public:
  OptionReader(const std::vector<std::string>& arguments, std::size_t first)
      : arguments(arguments), next(first)
  {
  }

  bool done() const { return next >= arguments.size(); }

  /// Next argument; for `--x=value` returns `--x` and stores the value for value_of().
  std::string take()
  {
    std::string argument = arguments[next++];
    std::string name, value;
    if (split_option(argument, name, value))
    {
      inline_value = value;
      has_inline_value = true;
      return name;
    }
    has_inline_value = false;
    return argument;
  }

  std::string value_of(const std::string& option)
  {
    if (has_inline_value)
    {
      has_inline_value = false;
      return inline_value;
    }
    if (done())
      throw CommandLineError("option " + option + " needs a value");
    return arguments[next++];
  }

private:
  const std::vector<std::string>& arguments;
  std::size_t next;
  std::string inline_value;
  bool has_inline_value = false;
};

void read_options(OptionReader& reader, CommandLine& line, const bool run)
{
  std::vector<deck::DeckOverride> sets, output, threads, restart;
  while (!reader.done())
  {
    const std::string argument = reader.take();
    if (argument == "--set")
    {
      const std::string value = reader.value_of(argument);
      sets.push_back({value, "--set '" + value + "'"});
    }
    else if (argument == "--output" && run)
    {
      const std::string value = reader.value_of(argument);
      output = {{"Output/Directory=" + value, "--output '" + value + "'"}};
    }
    else if (argument == "--threads" && run)
    {
      const std::string value = reader.value_of(argument);
      threads = {{"Run/Threads=" + value, "--threads " + value}};
    }
    else if (argument == "--restart" && run)
    {
      line.restart_directory = reader.value_of(argument);
      restart = {{"Output/Directory=" + line.restart_directory,
                  "--restart '" + line.restart_directory + "'"}};
    }
    else if (argument == "--deck" && line.command == CommandLine::Command::print_parameters)
      line.deck = reader.value_of(argument);
    else if (argument == "--help" || argument == "-h")
    {
      line.command = CommandLine::Command::help;
      return;
    }
    else if (argument.rfind("-", 0) == 0 && argument.size() > 1)
      throw CommandLineError("unknown option '" + argument + "'");
    else if (line.command == CommandLine::Command::print_parameters && line.output_file.empty())
      line.output_file = argument;
    else if (line.command != CommandLine::Command::print_parameters && line.deck.empty())
      line.deck = argument;
    else
      throw CommandLineError("unexpected argument '" + argument + "'");
  }
  line.overrides = sets;
  line.overrides.insert(line.overrides.end(), output.begin(), output.end());
  line.overrides.insert(line.overrides.end(), threads.begin(), threads.end());
  if (!restart.empty() && !output.empty())
    throw CommandLineError("--restart RUN_DIR continues in RUN_DIR; it cannot be combined with --output");
  line.overrides.insert(line.overrides.end(), restart.begin(), restart.end());
}
} // namespace

CommandLine parse_command_line(const int argc, const char* const* argv)
{
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  CommandLine line;
  if (arguments.empty())
    throw CommandLineError("no command given");

  const std::string& command = arguments[0];
  OptionReader reader(arguments, 1);
  if (command == "--help" || command == "-h" || command == "help")
    line.command = CommandLine::Command::help;
  else if (command == "--version")
    line.command = CommandLine::Command::version;
  else if (command == "run" || command == "check")
  {
    line.command = command == "run" ? CommandLine::Command::run : CommandLine::Command::check;
    read_options(reader, line, command == "run");
    if (line.command != CommandLine::Command::help && line.deck.empty())
      throw CommandLineError("'vulnus " + command + "' needs a deck file (DECK.prm)");
  }
  else if (command == "--print-parameters")
  {
    line.command = CommandLine::Command::print_parameters;
    read_options(reader, line, false);
  }
  else if (command == "point")
  {
    line.command = CommandLine::Command::point;
    line.arguments.assign(arguments.begin() + 1, arguments.end());
  }
  else if (command == "compare")
  {
    line.command = CommandLine::Command::compare;
    line.arguments.assign(arguments.begin() + 1, arguments.end());
    if (line.arguments.size() != 2)
      throw CommandLineError("'vulnus compare' needs exactly two run directories (RUN_A RUN_B)");
  }
  else
    throw CommandLineError("unknown command '" + command + "'");
  return line;
}

std::string usage_text()
{
  return "Usage:\n"
         "  vulnus run DECK.prm [--output DIR] [--set 'Section/Entry=value' ...] [--threads N]\n"
         "      Run the scene of a deck; results go to DIR (default runs/<deck name>).\n"
         "      --set overrides any deck entry (repeatable), checked like a deck line.\n"
         "  vulnus run DECK.prm --restart RUN_DIR [--set ...] [--threads N]\n"
         "      Continue a run (MPM, hybrid or FE) from the newest complete checkpoint in RUN_DIR (written\n"
         "      at Output/Checkpoint intervals and on SIGINT/SIGTERM); the deck's physics must\n"
         "      match the checkpoint's, Time/End time may grow.\n"
         "  vulnus check DECK.prm [--set ...]\n"
         "      Check a deck (and overrides) without running or writing anything; also\n"
         "      prints the warnings a run would give before its first step.\n"
         "  vulnus --print-parameters [FILE] [--deck DECK.prm] [--set ...]\n"
         "      Write every parameter with its default, allowed values and documentation,\n"
         "      as a valid deck (to FILE or the terminal); with --deck, as resolved from it.\n"
         "  vulnus point DECK.prm --material NAME --output OUT.csv\n"
         "        (--deformation F.csv | --path NAME --max VALUE --steps N) [--fiber x,y,z]\n"
         "      Drive one material point of the deck's material through a deformation history.\n"
         "  vulnus compare RUN_A RUN_B\n"
         "      Both summaries side by side with differences (tract areas by depth when the\n"
         "      runs slice the tract differently), and the failure fields of the points the\n"
         "      two runs share.\n"
         "  vulnus --help         This text.\n"
         "  vulnus --version      The version.\n"
         "Exit status: 0 success, 1 failure during a run, 2 bad command line or deck,\n"
         "  130 / 143 stopped by SIGINT / SIGTERM after writing a checkpoint.\n";
}

std::string version_text()
{
  return std::string("vulnus ") + VULNUS_VERSION + "\n";
}
} // namespace vulnus::app
