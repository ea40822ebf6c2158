// The time loop: start or restart, step, record, stop on signals or failures, summarise.
#include "simulator/simulator.h"
#include "analysis/momentum_audit.h"

#include "deck/scene_entries.h"
#include "mpm/rank_group.h"
#include "mpm/solver.h"
#include "io/summary_json.h"
#include "simulator/cavity_recorder.h"
#include "simulator/checkpointer.h"
#include "simulator/energy_guard.h"
#include "simulator/failure_report.h"
#include "simulator/history_writer.h"
#include "simulator/mesh_series.h"
#include "simulator/particle_series.h"
#include "simulator/scene_warnings.h"
#include "simulator/stop_signals.h"

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>

namespace vulnus::simulator
{
namespace
{
std::string format_seconds(const double s)
{
  std::ostringstream o;
  if (s < 120)
    o << std::fixed << std::setprecision(0) << s << " s";
  else
    o << std::fixed << std::setprecision(1) << s / 60 << " min";
  return o.str();
}

std::vector<std::unique_ptr<Postprocessor>> postprocessors_of(Stepper& stepper,
                                                              const deck::RunParameters& parameters,
                                                              io::RunDirectory& directory)
{
  std::vector<std::unique_ptr<Postprocessor>> list;
  list.push_back(std::make_unique<HistoryWriter>(directory, parameters.output.history_interval));
  if (stepper.mpm_side() != nullptr)
    list.push_back(std::make_unique<ParticleSeries>(
      directory.path(), parameters.output.particle_interval, stepper.communicator()));
  if (stepper.mpm_side() != nullptr)
    list.push_back(std::make_unique<CavityRecorder>());
  if (stepper.fe_side() != nullptr)
    list.push_back(
      std::make_unique<MeshSeries>(directory.path(), parameters.output.particle_interval,
                                   stepper.fe_material_id(), stepper.communicator()));
  return list;
}

class WallClock
{
public:
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

private:
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};
} // namespace

int simulate(Stepper& stepper, const deck::RunParameters& parameters, io::RunDirectory& directory)
{
  install_stop_signal_handlers();
  const WallClock wall;
  const mpm::RankGroup ranks(stepper.communicator());
  stepper.log_scene(directory);

  analysis::RunTotals totals;
  totals.wound_face_layer = parameters.output.wound_face_layer;
  totals.wound_outline_grid = parameters.output.wound_outline_grid;
  totals.warnings = scene_warnings(parameters, stepper.mpm_side() != nullptr);
  for (const std::string& w : totals.warnings)
    directory.warn(w);
  // The warnings the steps give follow these; checkpoints keep them (a restart gives the
  // scene's again), and the energy guard's flag with them.
  const auto n_scene_warnings = static_cast<std::ptrdiff_t>(totals.warnings.size());
  EnergyGuard energy_guard(parameters.energy_guard);

  const std::vector<std::unique_ptr<Postprocessor>> postprocessors =
    postprocessors_of(stepper, parameters, directory);
  Checkpointer checkpoints(parameters, directory, ranks);
  if (parameters.output.restart)
  {
    const io::RunProgress progress = checkpoints.restart(stepper, postprocessors);
    totals.warnings.insert(totals.warnings.end(), progress.warnings.begin(),
                           progress.warnings.end());
    energy_guard.restore(progress.energy_warned);
  }
  else
    for (const auto& p : postprocessors)
      p->start(stepper);
  auto write_checkpoint = [&](const double run_wall_seconds) {
    const std::vector<std::string> step_warnings(totals.warnings.begin() + n_scene_warnings,
                                                 totals.warnings.end());
    return checkpoints.write(stepper, postprocessors, step_warnings, energy_guard.has_warned(),
                             run_wall_seconds);
  };
  if (stepper.can_checkpoint())
    checkpoints.log_policy();
  else
    directory.log(std::string("checkpoints: none (") + stepper.method() +
                  " runs cannot write them yet); a stop signal ends the run with its records");

  auto last_good_state = [&] {
    std::string where = checkpoints.last_state();
    for (const auto& p : postprocessors)
      if (const std::string s = p->last_state(); !s.empty())
        where += (where.empty() ? "" : " and ") + s;
    return where;
  };

  auto guard_energy = [&](const bool final_check) {
    if (const auto warning = energy_guard.check(stepper, final_check))
    {
      directory.warn(*warning);
      totals.warnings.push_back(*warning);
    }
    for (const std::string& warning : stepper.check_validity(final_check))
    {
      directory.warn(warning);
      totals.warnings.push_back(warning);
    }
    for (const std::string& event : stepper.events())
      directory.log(event);
  };
  auto report_failure = [&](const std::exception& e) {
    const FailureReport report = describe_failure(e, deck::entry_of_scene_parameter);
    std::ostringstream o;
    o << report.kind << " at step " << stepper.step_count() << " (t = " << stepper.time()
      << " s): " << report.message;
    const std::string remedy = report.remedy.empty() ? stepper.blow_up_remedy() : report.remedy;
    totals.completed = false;
    totals.error = o.str() + "; likely remedy: " + remedy;
    directory.warn(o.str());
    directory.warn("likely remedy: " + remedy);
    directory.warn("the last good state is " + last_good_state());
  };

  auto report_output_failure = [&](const std::exception& e) {
    std::ostringstream o;
    o << "output failed at step " << stepper.step_count() << " (t = " << stepper.time()
      << " s): " << e.what();
    std::error_code code;
    const std::filesystem::space_info space = std::filesystem::space(directory.path(), code);
    if (!code)
      o << "; " << std::fixed << std::setprecision(1) << double(space.available) / 1e9
        << " GB free where the run writes (a full disk is the usual cause; a larger "
           "Output/Particle output interval writes less)";
    totals.completed = false;
    totals.error = o.str();
    directory.warn(o.str());
    directory.warn("the last good state is " + last_good_state());
  };

  double last_progress = 0.0;
  const double first_time = stepper.time(); // later than 0 after a restart
  int stop_signal = 0;
  while (!stepper.finished())
  {
    // Ranks may see a signal at different steps: stop together on the first one seen.
    if ((stop_signal = static_cast<int>(ranks.max(pending_stop_signal()))) != 0)
      break;
    try
    {
      stepper.advance();
    }
    catch (const std::exception& e)
    {
      report_failure(e);
      break;
    }
    try
    {
      for (const auto& p : postprocessors)
        p->after_step(stepper);
    }
    catch (const std::exception& e)
    {
      report_output_failure(e);
      break;
    }
    try
    {
      guard_energy(false);
    }
    catch (const std::exception& e)
    {
      report_failure(e); // the step is recorded; the state is past the limit
      break;
    }
    const double seconds = ranks.max(wall.seconds()); // the same on every rank
    if (checkpoints.due(stepper, seconds))
      directory.log("checkpoint: " + write_checkpoint(seconds));
    if (seconds - last_progress >= 5.0)
    {
      last_progress = seconds;
      const double rate = (stepper.time() - first_time) / seconds; // simulated s per wall s
      std::ostringstream o;
      o << "t = " << std::scientific << std::setprecision(3) << stepper.time() << " s, step "
        << stepper.step_count() << ", dt = " << stepper.last_time_step() << " s, "
        << stepper.progress() << ", time left about "
        << format_seconds((stepper.expected_end_time() - stepper.time()) / rate);
      directory.log(o.str());
    }
  }

  if (stop_signal != 0)
  {
    std::ostringstream o;
    o << "stopped by " << stop_signal_name(stop_signal) << " at step " << stepper.step_count();
    if (stepper.can_checkpoint())
    {
      directory.warn(o.str() + "; checkpoint " + write_checkpoint(ranks.max(wall.seconds())) +
                     "; continue with `vulnus run DECK --restart " + directory.path() + "`");
      return 128 + stop_signal;
    }
    totals.completed = false;
    totals.error = o.str() + " (no checkpoint: " + stepper.method() + " runs cannot write one yet)";
    directory.warn(totals.error);
  }
  if (totals.completed && stop_signal == 0)
    try
    {
      guard_energy(true);
    }
    catch (const std::exception& e)
    {
      report_failure(e);
    }
  for (const auto& p : postprocessors)
    if (totals.completed)
      p->finish(stepper);
    else
      p->flush();
  totals.wall_seconds = checkpoints.earlier_wall_seconds() + wall.seconds();

  for (const std::string& w : stepper.final_warnings())
  {
    directory.warn(w);
    totals.warnings.push_back(w);
  }
  nlohmann::json summary = stepper.summary(totals); // collective
  for (const auto& p : postprocessors)
    p->add_to_summary(summary);
  const int status = stop_signal != 0 ? 128 + stop_signal : totals.completed ? 0 : 1;
  if (!directory.writes_files())
    return status;
  // A run stopped by an error is audited in the state it stopped in, which may be inside a
  // coupling window with the far field's share of the impulse not yet given: no warning.
  if (const std::optional<std::string> audit = analysis::momentum_audit_warning(summary);
      audit && totals.completed)
  {
    directory.warn(*audit);
    totals.warnings.push_back(*audit);
  }
  summary["warnings"] = totals.warnings;
  io::write_summary_json(directory.file("summary.json"), summary);
  directory.log(stepper.final_report(summary));
  return status;
}
} // namespace vulnus::simulator
