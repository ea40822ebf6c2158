// The pure-FE stepper: steps, history rows and summary of a far-field-only scene.
#include "simulator/fe_stepper.h"

#include "analysis/momentum_audit.h"
#include "analysis/wound_metrics.h"

#include "deck/method_checks.h"
#include "io/run_directory.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace vulnus::simulator
{
namespace
{
/// Energy balance of a scene driven by external work W from rest: (E - W) / W_in, with E the
/// kinetic, strain and dissipated energy and W_in the energy the loads have put in (a load
/// that takes the energy back, as a velocity pulse on a face does once the wave returns,
/// leaves W near zero: relative to W the round-off of a good run then reads as a blow-up).
double balance_error(const fem::FeDiagnostics& d)
{
  const double accounted = d.kinetic_energy + d.strain_energy + d.dissipated_energy;
  const double scale = std::max(std::abs(d.external_work), d.external_work_in);
  return scale != 0.0 ? (accounted - d.external_work) / scale : 0.0;
}
} // namespace

FeStepper::FeStepper(const deck::RunParameters& run, const MPI_Comm communicator)
    : parameters(deck::pure_fe_scene(run)),
      solver(std::make_unique<fem::FarFieldSolver>(parameters, communicator))
{
  solver->setup();
  const fem::FeDiagnostics d = solver->diagnostics(); // collective
  initial_momentum = Eigen::Vector3d(d.momentum[0], d.momentum[1], d.momentum[2]);
}

void FeStepper::advance()
{
  dt = std::min(solver->next_time_step(), parameters.end_time - solver->time());
  solver->advance(dt);
}

bool FeStepper::finished() const { return solver->time() >= parameters.end_time * (1.0 - 1e-12); }

void FeStepper::log_scene(io::RunDirectory& directory) const
{
  const unsigned long long n_points = solver->n_quadrature_points(); // collective
  std::ostringstream o;
  o << "FE scene: " << solver->n_active_cells() << " cells, " << solver->n_dofs() << " dofs, "
    << n_points << " quadrature points, Q" << parameters.degree << " ("
    << fem::integration_description(parameters) << ", "
    << fem::shock_viscosity_description(parameters) << "), "
    << dealii::Utilities::MPI::n_mpi_processes(solver->communicator()) << " MPI rank(s)";
  directory.log(o.str());
}

std::string FeStepper::progress() const
{
  return "failed quadrature points " + std::to_string(solver->diagnostics().n_failed_points);
}

double FeStepper::energy_balance_error() const
{
  return balance_error(solver->diagnostics());
}

std::string FeStepper::energy_error_causes() const
{
  return "a Far field/CFL (explicit) or time step (implicit) too large for the load, or a "
         "load that deforms the mesh beyond what it resolves";
}

std::string FeStepper::blow_up_remedy() const
{
  return "a smaller Far field/CFL (explicit) or time step (implicit), or a smaller Far field "
         "load: an inverted element or a solver that does not converge means the load deforms "
         "the mesh beyond what it can represent";
}

std::vector<std::string> FeStepper::history_columns() const
{
  return {"time_s",       "dt_s",       "step",       "kinetic_J",
          "strain_J",     "dissipated_material_J",    "external_work_J",
          "energy_balance_error",       "momentum_x", "momentum_y",
          "momentum_z",   "failed_points",
          "support_impulse_x-", "support_impulse_x+", "support_impulse_y-",
          "support_impulse_y+", "support_impulse_z-", "support_impulse_z+"};
}

std::vector<double> FeStepper::history_row() const
{
  const fem::FeDiagnostics d = solver->diagnostics(); // collective
  // Each face's impulse along its own normal axis (N s), as in the MPM and hybrid histories.
  const auto normal = [&d](const unsigned int f) { return d.support_impulses[f][f / 2]; };
  return {d.time,
          dt,
          double(d.step),
          d.kinetic_energy,
          d.strain_energy,
          d.dissipated_energy,
          d.external_work,
          balance_error(d),
          d.momentum[0],
          d.momentum[1],
          d.momentum[2],
          double(d.n_failed_points),
          normal(0), normal(1), normal(2), normal(3), normal(4), normal(5)};
}

std::vector<std::string> FeStepper::final_warnings() const
{
  const unsigned long long failed = solver->diagnostics().n_failed_points; // collective
  if (failed == 0)
    return {};
  return {"*** " + std::to_string(failed) +
          " FE quadrature points failed: the material tore, which a pure-FE scene cannot "
          "follow (no erosion, no particles); run the scene as MPM or hybrid"};
}

nlohmann::json FeStepper::summary(const analysis::RunTotals& totals) const
{
  const fem::FeDiagnostics d = solver->diagnostics(); // collective
  const unsigned long long cells = solver->n_active_cells();
  const unsigned long long dofs = solver->n_dofs();
  if (dealii::Utilities::MPI::this_mpi_process(solver->communicator()) != 0)
    return {};
  nlohmann::json summary;
  summary["method"] = "FE";
  summary["completed"] = totals.completed;
  if (!totals.completed)
    summary["error"] = totals.error;
  summary["particles"] = 0;
  summary["mpi"] = {{"ranks", dealii::Utilities::MPI::n_mpi_processes(solver->communicator())}};
  summary["fe_cells"] = cells;
  summary["fe_dofs"] = dofs;
  summary["steps"] = solver->step_number();
  summary["time_s"] = solver->time();
  summary["wall_seconds"] = totals.wall_seconds;
  summary["fe_failed_points"] = d.n_failed_points;
  summary["energy"] = {{"initial_J", 0.0},
                       {"kinetic_J", d.kinetic_energy},
                       {"strain_J", d.strain_energy},
                       {"dissipated_J", d.dissipated_energy},
                       {"external_work_J", d.external_work},
                       {"external_work_in_J", d.external_work_in},
                       {"balance_error", balance_error(d)}};
  // The supports of every face; the momentum audit (a traction load's impulse is not booked,
  // so a scene with one has no audit).
  analysis::MomentumAudit audit;
  audit.initial = initial_momentum;
  audit.now = Eigen::Vector3d(d.momentum[0], d.momentum[1], d.momentum[2]);
  bool loaded_by_traction = false;
  for (unsigned int f = 0; f < fem::n_slab_faces; ++f)
  {
    const dealii::Tensor<1, 3>& j = d.support_impulses[f];
    summary["supports"][analysis::box_face_name(static_cast<int>(f))] = {
      {"impulse_N_s", {j[0], j[1], j[2]}}};
    audit.add_support(Eigen::Vector3d(j[0], j[1], j[2]));
    loaded_by_traction = loaded_by_traction || parameters.faces[f].condition ==
                                                 fem::FaceParameters::Condition::traction;
  }
  summary["momentum_audit"] =
    loaded_by_traction ? nlohmann::json() : analysis::momentum_audit_json(audit);
  return summary;
}

std::string FeStepper::final_report(const nlohmann::json& summary) const
{
  std::ostringstream o;
  o << std::setprecision(4) << "done: " << summary["steps"] << " FE steps to t = "
    << summary["time_s"].get<double>() << " s in " << summary["wall_seconds"].get<double>()
    << " s wall; energy balance error " << summary["energy"]["balance_error"].get<double>()
    << "; failed quadrature points " << summary["fe_failed_points"];
  return o.str();
}
} // namespace vulnus::simulator
