// The subcommands of `vulnus`: run, check, --print-parameters.
#include "app/commands.h"

#include "io/mpi_launch.h"

#include "io/atomic_file.h"
#include "deck/deck_reader.h"
#include "io/run_directory.h"
#include "simulator/checkpointer.h"
#include "simulator/scene_warnings.h"
#include "simulator/simulation_runner.h"
#include "simulator/zone_end_guard.h"
#include "deck/version.h"

#include <exception>
#include <iostream>

namespace vulnus::app
{
using deck::DeckError;
using deck::RunParameters;
using deck::read_run_parameters;
using io::RunDirectory;
using io::launcher_rank;
using simulator::run_simulation;
using deck::Method;
using deck::DeckOverride;
using io::default_run_directory;
using io::write_file_atomically;

namespace
{
void report(const DeckError& error)
{
  for (const std::string& message : error.messages())
    std::cerr << "vulnus: error: " << message << '\n';
  std::cerr << "vulnus: the deck was not run (see `vulnus --print-parameters` for every entry)\n";
}
} // namespace

int run_command(const CommandLine& line)
{
  RunParameters parameters;
  try
  {
    parameters = read_run_parameters(line.deck, line.overrides);
  }
  catch (const DeckError& error)
  {
    // Every rank of an mpirun found the same problem; rank 0 reports it and carries the exit
    // status. The others leave quietly: a non-zero exit of theirs makes mpirun kill rank 0
    // before its report reaches the terminal.
    if (launcher_rank() != 0)
      return 0;
    report(error);
    return 2;
  }
  parameters.output.restart = !line.restart_directory.empty();

  try
  {
    const std::string path = parameters.output.directory.empty() ? default_run_directory(line.deck)
                                                                 : parameters.output.directory;
    RunDirectory directory(path, launcher_rank() == 0);
    if (!parameters.output.restart) // a restart writes it once the checkpoint matches the deck
      directory.write_deck_used(parameters.resolved_deck);
    directory.log(std::string("vulnus ") + VULNUS_VERSION + " run " + line.deck +
                  (parameters.output.restart ? " (restart)" : ""));
    for (const DeckOverride& override_ : line.overrides)
      directory.log("  override " + override_.origin);
    directory.log("run directory: " + directory.path());
    return run_simulation(parameters, directory);
  }
  catch (const simulator::RestartRefused& error) // the deck is wrong for this run
  {
    std::cerr << "vulnus: error: " << error.what() << '\n';
    return 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << "vulnus: error: " << error.what() << '\n';
    return 1;
  }
}

int check_command(const CommandLine& line)
{
  RunParameters parameters;
  try
  {
    parameters = read_run_parameters(line.deck, line.overrides);
  }
  catch (const DeckError& error)
  {
    report(error);
    return 2;
  }
  // What a run would warn about before its first step: the deck runs, but may mislead.
  const bool has_mpm_side = parameters.method == Method::mpm;
  for (const std::string& warning : simulator::scene_warnings(parameters, has_mpm_side))
    std::cerr << "vulnus: warning: " << warning << '\n';
  if (const std::string note = simulator::zone_end_note(parameters); !note.empty())
    std::cout << "vulnus: note: " << note << '\n';
  std::cout << line.deck << ": deck OK\n";
  return 0;
}

int print_parameters_command(const CommandLine& line)
{
  std::string listing;
  try
  {
    listing = parameter_listing(line.deck, line.overrides);
  }
  catch (const DeckError& error)
  {
    for (const std::string& message : error.messages())
      std::cerr << "vulnus: error: " << message << '\n';
    return 2;
  }
  if (line.output_file.empty())
  {
    std::cout << listing;
    return 0;
  }
  try
  {
    write_file_atomically(line.output_file, [&](std::ostream& out) { out << listing; });
  }
  catch (const std::exception& error)
  {
    std::cerr << "vulnus: error: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
} // namespace vulnus::app
