// Checkpoint policy, writing and restart.
#include "simulator/checkpointer.h"

#include "deck/deck_difference.h"
#include "deck/deck_reader.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace vulnus::simulator
{
namespace
{
/// Entries a restart may change: where and how often things are written, threads, and the
/// end and step size of the time integration (to extend a run, or to continue a blown-up
/// run from its last checkpoint with a smaller CFL).
const std::vector<std::string> restart_may_change = {
  "Output/", "Run/Threads", "Time/End time", "Time/CFL", "Time/Maximum time step",
  "Time/Stop when projectile exits", "Time/Stop when projectile stops", "Time/Projectile stop speed"};

/// Each rank of a distributed run keeps its own checkpoints in checkpoints/rank_R.
std::string checkpoint_folder(const mpm::RankGroup& ranks)
{
  return ranks.distributed() ? "checkpoints/rank_" + std::to_string(ranks.rank()) : "checkpoints";
}

/// The rank count whose checkpoints `folder` holds: the number of rank_R folders (0 for a
/// serial run's layout).
int ranks_of_checkpoints(const std::filesystem::path& folder)
{
  int n = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.is_directory() && entry.path().filename().string().rfind("rank_", 0) == 0)
      ++n;
  return n;
}
} // namespace

Checkpointer::Checkpointer(const deck::RunParameters& parameters, io::RunDirectory& directory,
                           const mpm::RankGroup& ranks)
    : parameters(parameters), directory(directory), ranks(ranks),
      store(directory.path(), parameters.output.checkpoints_kept, checkpoint_folder(ranks))
{
}

io::RunProgress
Checkpointer::restart(Stepper& stepper,
                      const std::vector<std::unique_ptr<Postprocessor>>& postprocessors)
{
  const int written_on = ranks_of_checkpoints(directory.file("checkpoints"));
  const int running_on = ranks.distributed() ? ranks.size() : 0;
  if (written_on != running_on)
    throw RestartRefused(
      "--restart: the checkpoints in " + directory.file("checkpoints") + " were written by a run on " +
      (written_on == 0 ? std::string("1 process") : std::to_string(written_on) + " MPI ranks") +
      ", this run has " +
      (running_on == 0 ? std::string("1 process") : std::to_string(running_on) + " ranks") +
      "; restart on the same count (" +
      (written_on == 0 ? std::string("without mpirun, or -np 1") : "mpirun -np " + std::to_string(written_on)) + ")");
  // A checkpoint written before an entry existed ran as that entry's default does.
  const std::string defaults = deck::parameter_listing();
  std::vector<std::string> taken_at_default;
  auto refuse_a_different_deck = [&](const std::string& checkpoint_deck, const std::string& which) {
    const std::string difference = deck::first_deck_difference(
      checkpoint_deck, parameters.resolved_deck, restart_may_change, defaults, taken_at_default);
    if (!difference.empty())
      throw RestartRefused("--restart: the deck does not match the checkpoint " + which + ": " +
                           difference + ". Restart with the run's deck (" +
                           directory.file("deck_used.prm") + ") and its --set entries");
  };
  // The deck first: a restart without an earlier --set would otherwise fail to restore every
  // checkpoint and call them all damaged.
  if (const std::string deck = store.newest_deck(); !deck.empty())
    refuse_a_different_deck(deck, "(the newest)");
  std::string used;
  const io::RunProgress progress =
    store.read_newest([&](std::istream& in) { stepper.restore(in); },
                      [&](const std::string& line) { directory.warn(line); }, used);
  const double step = static_cast<double>(stepper.step_count());
  if (ranks.max(step) != -ranks.max(-step))
    throw std::runtime_error("--restart: the ranks' newest complete checkpoints are of different "
                             "steps (one rank's newest is damaged); remove the newer ones under " +
                             directory.file("checkpoints") + " so that every rank has the same newest step");
  refuse_a_different_deck(progress.resolved_deck, "'" + used + "'"); // an older one was used
  directory.write_deck_used(parameters.resolved_deck);
  for (const auto& p : postprocessors)
    p->resume(stepper, progress);
  wall_before_restart = progress.wall_seconds;
  newest = used;
  newest_step = stepper.step_count();
  std::ostringstream o;
  o << "restarted from " << used << ": step " << stepper.step_count() << ", t = " << stepper.time()
    << " s, the outputs, the history and the warnings so far kept";
  directory.log(o.str());
  if (!taken_at_default.empty())
  {
    std::string entries;
    for (const std::string& path : taken_at_default)
      entries += (entries.empty() ? "" : ", ") + path;
    directory.log("the checkpoint was written before these entries existed; they keep their "
                  "defaults: " + entries);
  }
  return progress;
}

bool Checkpointer::due(const Stepper& stepper, const double run_wall_seconds) const
{
  if (!stepper.can_checkpoint())
    return false;
  const deck::OutputParameters& o = parameters.output;
  if (o.checkpoint_step_interval > 0 && stepper.step_count() % o.checkpoint_step_interval == 0 &&
      stepper.step_count() != newest_step)
    return true;
  return o.checkpoint_wall_interval > 0 &&
         run_wall_seconds - wall_at_last_checkpoint >= o.checkpoint_wall_interval;
}

std::string Checkpointer::write(const Stepper& stepper,
                                const std::vector<std::unique_ptr<Postprocessor>>& postprocessors,
                                const std::vector<std::string>& warnings, const bool energy_warned,
                                const double run_wall_seconds)
{
  io::RunProgress progress;
  progress.resolved_deck = parameters.resolved_deck;
  progress.warnings = warnings;
  progress.energy_warned = energy_warned;
  for (const auto& p : postprocessors)
  {
    p->flush();
    p->save_progress(progress);
  }
  progress.wall_seconds = wall_before_restart + run_wall_seconds;
  newest = store.write(stepper.step_count(), progress,
                       [&](std::ostream& out) { stepper.save(out); });
  newest_step = stepper.step_count();
  wall_at_last_checkpoint = run_wall_seconds;
  return newest;
}

std::string Checkpointer::last_state() const
{
  if (newest.empty())
    return {};
  std::ostringstream o;
  o << "the checkpoint of step " << newest_step << " (" << newest
    << "; continue with `vulnus run DECK --restart " << directory.path()
    << "`, a smaller Time/CFL is allowed)";
  return o.str();
}

void Checkpointer::log_policy() const
{
  const deck::OutputParameters& output = parameters.output;
  std::ostringstream o;
  o << "checkpoints: ";
  if (output.checkpoint_step_interval > 0)
    o << "every " << output.checkpoint_step_interval << " steps, ";
  if (output.checkpoint_wall_interval > 0)
    o << "every " << output.checkpoint_wall_interval << " s of wall time, ";
  o << "on SIGINT/SIGTERM; newest " << output.checkpoints_kept << " kept in "
    << directory.file("checkpoints");
  directory.log(o.str());
}
} // namespace vulnus::simulator
