// History, particle output and checkpoints of a pure-MPM run, fresh or restarted.
#include "app/mpm_run_files.h"

#include "app/deck_difference.h"
#include "app/mpm_history.h"
#include "app/mpm_snapshot.h"

#include <sstream>
#include <stdexcept>

namespace vulnus::app
{
namespace
{
/// Entries a restart may change: where and how often things are written, threads, and the
/// end and step size of the time integration (to extend a run, or to continue a blown-up
/// run from its last checkpoint with a smaller CFL).
const std::vector<std::string> restart_may_change = {
  "Output/", "Run/Threads", "Time/End time", "Time/CFL", "Time/Maximum time step",
  "Time/Stop when projectile exits"};
} // namespace

namespace
{
/// Each rank of a distributed run keeps its own checkpoints in checkpoints/rank_R.
std::string checkpoint_folder(const mpm::RankGroup& ranks)
{
  return ranks.distributed() ? "checkpoints/rank_" + std::to_string(ranks.rank()) : "checkpoints";
}
} // namespace

MpmRunFiles::MpmRunFiles(const RunParameters& parameters, RunDirectory& directory,
                         const mpm::RankGroup& ranks)
    : parameters(parameters), directory(directory), ranks(ranks),
      output(directory.path(), "particles", ranks.communicator()),
      checkpoints(directory.path(), parameters.output.checkpoints_kept, checkpoint_folder(ranks))
{
}

void MpmRunFiles::add_history_row(const mpm::Solver& solver)
{
  const std::vector<double> row = mpm_history_row(solver, solver.diagnostics()); // collective
  if (history)
    history->add_row(row);
}

void MpmRunFiles::start(mpm::Solver& solver)
{
  if (parameters.output.restart)
  {
    restart(solver);
    return;
  }
  if (directory.writes_files())
    history = std::make_unique<CsvHistory>(directory.file("history.csv"), mpm_history_columns());
  output.write(solver.time(), mpm_snapshot(solver));
  const double interval = parameters.output.particle_interval;
  next_output = interval > 0 ? interval : parameters.scene.end_time * 2;
  add_history_row(solver);
}

void MpmRunFiles::restart(mpm::Solver& solver)
{
  std::string used;
  const RunProgress progress =
    checkpoints.read_newest([&](std::istream& in) { solver.restore(in); },
                            [&](const std::string& line) { directory.warn(line); }, used);
  const double step = static_cast<double>(solver.step_count());
  if (ranks.max(step) != -ranks.max(-step))
    throw std::runtime_error("--restart: the ranks' newest complete checkpoints are of different "
                             "steps (one rank's newest is damaged); remove the newer ones under " +
                             directory.file("checkpoints") + " so that every rank has the same newest step");
  const std::string difference =
    first_deck_difference(progress.resolved_deck, parameters.resolved_deck, restart_may_change);
  if (!difference.empty())
    throw std::runtime_error("--restart: the deck does not match the checkpoint '" + used +
                             "': " + difference + ". Restart with the run's deck (" +
                             directory.file("deck_used.prm") + ")");
  directory.write_deck_used(parameters.resolved_deck);
  std::istringstream records(progress.output_records);
  output.restore_records(records);
  if (directory.writes_files())
    history = std::make_unique<CsvHistory>(CsvHistory::resume(
      directory.file("history.csv"), mpm_history_columns(), progress.history_bytes));
  next_output = progress.next_output;
  wall_before_restart = progress.wall_seconds;
  newest_checkpoint = used;
  newest_checkpoint_step = solver.step_count();
  std::ostringstream o;
  o << "restarted from " << used << ": step " << solver.step_count() << ", t = " << solver.time()
    << " s, " << output.n_outputs() << " particle outputs and the history so far kept";
  directory.log(o.str());
}

void MpmRunFiles::after_step(const mpm::Solver& solver)
{
  if (solver.step_count() % parameters.output.history_interval == 0)
    add_history_row(solver);
  if (solver.time() >= next_output * (1 - 1e-12))
  {
    output.write(solver.time(), mpm_snapshot(solver));
    next_output += parameters.output.particle_interval;
  }
}

void MpmRunFiles::finish(const mpm::Solver& solver)
{
  add_history_row(solver);
  if (!output.has_output_at(solver.time()))
    output.write(solver.time(), mpm_snapshot(solver));
  if (history)
    history->flush();
}

bool MpmRunFiles::checkpoint_due(const mpm::Solver& solver, const double run_wall_seconds) const
{
  const OutputParameters& o = parameters.output;
  if (o.checkpoint_step_interval > 0 && solver.step_count() % o.checkpoint_step_interval == 0 &&
      solver.step_count() != newest_checkpoint_step)
    return true;
  return o.checkpoint_wall_interval > 0 &&
         run_wall_seconds - wall_at_last_checkpoint >= o.checkpoint_wall_interval;
}

std::string MpmRunFiles::write_checkpoint(const mpm::Solver& solver, const double run_wall_seconds)
{
  if (history)
    history->flush();
  RunProgress progress;
  progress.resolved_deck = parameters.resolved_deck;
  progress.next_output = next_output;
  progress.history_bytes = history ? history->bytes_written() : 0;
  progress.wall_seconds = wall_before_restart + run_wall_seconds;
  std::ostringstream records;
  output.save_records(records);
  progress.output_records = records.str();
  newest_checkpoint = checkpoints.write(solver.step_count(), progress,
                                        [&](std::ostream& out) { solver.save(out); });
  newest_checkpoint_step = solver.step_count();
  wall_at_last_checkpoint = run_wall_seconds;
  return newest_checkpoint;
}

std::string MpmRunFiles::last_good_state() const
{
  std::ostringstream o;
  if (!newest_checkpoint.empty())
    o << "the checkpoint of step " << newest_checkpoint_step << " (" << newest_checkpoint
      << "; continue with `vulnus run DECK --restart " << directory.path()
      << "`, a smaller Time/CFL is allowed) and ";
  o << "the last particle output (t = " << output.last_time() << " s) in " << output.xdmf_path();
  return o.str();
}
} // namespace vulnus::app
