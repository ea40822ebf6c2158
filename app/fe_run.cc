// Pure-FE run: the library driver plus the run directory's log and summary.json.
#include "app/fe_run.h"

#include "app/log_stream.h"
#include "app/method_checks.h"
#include "app/summary_json.h"
#include "fem/fe_scene.h"

#include <mpi.h>

namespace vulnus::app
{
int run_fe_scene(const RunParameters& parameters, RunDirectory& directory)
{
  fem::FeSceneParameters fe = pure_fe_scene(parameters);
  fe.output_interval = parameters.output.particle_interval;
  fe.log_interval = std::max(1u, parameters.output.history_interval);
  LogStream log(directory.logger());
  nlohmann::json summary;
  summary["method"] = "FE";
  summary["particles"] = 0;
  try
  {
    const fem::FeSceneResult r = fem::run_fe_scene(fe, directory.path(), log, MPI_COMM_WORLD);
    summary["completed"] = true;
    summary["fe_cells"] = r.n_cells;
    summary["fe_dofs"] = r.n_dofs;
    summary["steps"] = r.n_steps;
    summary["time_s"] = r.time;
    summary["wall_seconds"] = r.wall_seconds;
    summary["fe_failed_points"] = r.n_failed_points;
    const double accounted = r.kinetic_energy + r.strain_energy + r.dissipated_energy;
    summary["energy"] = {{"initial_J", 0.0},
                         {"kinetic_J", r.kinetic_energy},
                         {"strain_J", r.strain_energy},
                         {"dissipated_J", r.dissipated_energy},
                         {"external_work_J", r.external_work},
                         {"balance_error", r.external_work != 0.0
                                             ? (accounted - r.external_work) / r.external_work
                                             : 0.0}};
    std::vector<std::string> warnings;
    if (r.n_failed_points > 0)
      warnings.push_back(std::to_string(r.n_failed_points) + " FE quadrature points failed");
    summary["warnings"] = warnings;
    write_summary_json(directory.file("summary.json"), summary);
    return 0;
  }
  catch (const std::runtime_error& e)
  {
    directory.warn(std::string("FE solution broke down: ") + e.what());
    summary["completed"] = false;
    summary["error"] = e.what();
    write_summary_json(directory.file("summary.json"), summary);
    return 1;
  }
}
} // namespace vulnus::app
