// The pure-MPM stepper: scene log, history rows, summary and closing line.
#include "simulator/mpm_stepper.h"

#include "analysis/wound_sample.h"
#include "io/run_directory.h"
#include "simulator/mpm_history.h"
#include "simulator/rigid_hold_report.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace vulnus::simulator
{
ProjectileStart projectile_start(const mpm::Solver& solver)
{
  const mpm::SceneDiagnostics initial = solver.diagnostics(); // collective
  if (solver.projectile() < 0)
    return {};
  const mpm::BodySummary& b = initial.bodies[solver.projectile()];
  return {b.velocity.dot(solver.flight_direction()), b.kinetic_energy};
}

namespace
{
/// On a graded grid, whether the wound (the failed points' places in the body as it was
/// built) or the projectile at its end lie in cells wider than the fine box's: the contact gap,
/// the cavity's wall and the wound are measured with the fine cell's point spacing.
std::string graded_grid_warning(const mpm::Solver& solver)
{
  const mpm::Grid& grid = solver.background_grid();
  if (!grid.graded())
    return {};
  const mpm::Particles& p = solver.points();
  double projectile = grid.cell_size(), wound = grid.cell_size();
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
    for (std::size_t i = p.begin_of(b); i < p.end_of(b); ++i)
      if (int(b) == solver.projectile())
        projectile = std::max(projectile, grid.widest_cell_side(p.position[i]));
      else if (p.failure[i] != 0) // where it failed: debris flung off the face is not the wound
        wound = std::max(wound, grid.widest_cell_side(p.reference_position[i].cast<double>()));
  const double h = grid.cell_size();
  if (projectile <= 1.001 * h && wound <= 1.001 * h)
    return {};
  std::ostringstream o;
  o << std::setprecision(3);
  if (projectile > 1.001 * h)
    o << "the projectile ended in cells up to " << projectile / h << " times Grid/Cell size wide";
  if (wound > 1.001 * h)
    o << (projectile > 1.001 * h ? ", and " : "") << "points failed in cells up to "
      << wound / h << " times Grid/Cell size wide";
  o << ", outside Grid/Grading/Fine box: contact, the cavity and the wound are measured with the "
       "fine cells' point spacing and are not resolved there; enlarge the fine box along the "
       "path (a projectile that perforated and flew on may be ignored)";
  return o.str();
}
} // namespace

std::vector<std::string> mpm_final_warnings(const mpm::Solver& solver)
{
  std::vector<std::string> warnings;
  if (solver.projectile() >= 0 && !solver.body_material(solver.projectile()).is_rigid() &&
      !solver.scene().subcycle_projectile && solver.uses_contact() &&
      !solver.projectile_hold().record().held)
    warnings.push_back(
      "the deformable projectile was not subcycled (Time/Subcycle projectile = false): its "
      "wound is not converged in the time step (in the paper scenes its exit velocity falls "
      "about 1 % per halving of the step, and the step follows the projectile's wave speed; "
      "docs/converged_wound.md sections 12-13); subcycling gives the converged answer at the "
      "target's step");
  if (const std::string surface = rigid_hold_surface_warning(solver); !surface.empty())
    warnings.push_back(surface);
  if (const std::string rotation = rigid_rotation_warning(solver); !rotation.empty())
    warnings.push_back(rotation);
  if (solver.projectile() >= 0)
  {
    // A projectile that left the grid only in part: what is reported of it is what stayed.
    const mpm::Particles& p = solver.points();
    std::uint64_t counts[2] = {0, p.end_of(solver.projectile()) - p.begin_of(solver.projectile())};
    for (const mpm::DepartedPoint& d : solver.departed_points())
      counts[0] += static_cast<int>(d.body) == solver.projectile();
    solver.rank_group().sum(counts, 2);
    if (counts[0] > 0 && counts[1] > 0)
      warnings.push_back(
        std::to_string(counts[0]) + " of the projectile's " + std::to_string(counts[0] + counts[1]) +
        " points left the grid and were removed: its velocity, energy and fate describe only the " +
        std::to_string(counts[1]) + " that stayed; enlarge Grid/Domain min and max along its path");
  }
  if (const std::string graded = graded_grid_warning(solver); !graded.empty())
    warnings.push_back(graded);
  if (solver.removed_points() > 0)
    warnings.push_back(std::to_string(solver.removed_points()) +
                       " points left the grid and were removed; their energy is booked "
                       "as outflow");
  return warnings;
}

MpmStepper::MpmStepper(const deck::RunParameters& parameters, const MPI_Comm communicator)
    : solver(parameters.scene, communicator), n_points_at_start(solver.n_points_all_ranks()),
      projectile(projectile_start(solver))
{
}

void MpmStepper::log_scene(io::RunDirectory& directory) const
{
  const mpm::SceneParameters& scene = solver.scene();
  const mpm::Particles& p = solver.points();
  std::vector<std::uint64_t> body_points(p.n_bodies());
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
    body_points[b] = p.end_of(b) - p.begin_of(b);
  solver.rank_group().sum(body_points.data(), static_cast<int>(body_points.size()));
  std::ostringstream o;
  o << "MPM scene: " << solver.n_points_all_ranks() << " points, cell size " << scene.cell_size << " m, grid "
    << solver.background_grid().cells()[0] << " x " << solver.background_grid().cells()[1]
    << " x " << solver.background_grid().cells()[2] << " cells";
  if (solver.background_grid().graded())
    o << " (graded: up to " << scene.grading.largest_cells << " times the cell outside the fine box)";
  o << ", "
    << mpm::shape_function_name(scene.shape_function)
    << " shape functions, " << (scene.update_scheme == mpm::UpdateScheme::musl ? "MUSL" : "USL")
    << ", " << omp_get_max_threads() << " thread(s)"
    << mpm::describe_mirror_planes(solver.mirror_planes());
  if (solver.rank_group().distributed())
  {
    o << " on each of " << solver.rank_group().size() << " ranks; slabs along axis "
      << solver.slabs().axis() << " from cell layers";
    for (int r = 1; r < solver.rank_group().size(); ++r)
      o << ' ' << solver.slabs().first_layers()[r];
    o << ", re-cut to balance the points every " << scene.sort_interval << " steps";
  }
  directory.log(o.str());
  for (std::size_t b = 0; b < p.n_bodies(); ++b)
  {
    const mpm::BodyParameters& body = scene.bodies[b];
    const materials::Material& m = solver.body_material(b);
    std::ostringstream line;
    line << "  body " << body.name << ": " << body_points[b] << " points, material "
         << body.material << " (" << m.model_name() << ")";
    if (m.is_rigid())
      line << ", rigid: no stress update, no time-step limit";
    else if (m.model_name().find("hyperelastic") != std::string::npos)
    {
      const materials::FailureParameters& failure =
        mpm::find_material(scene, body.material)->parameters.tissue.failure;
      const bool zero_rule =
        failure.stress_after_failure == materials::StressAfterFailure::zero;
      line << (m.uses_fibers() ? "" : ", no fiber work")
           << (!failure.enabled ? ", failure off: no eigenvalues"
               : zero_rule      ? ", failed tissue carries no pressure (the paper's rule)"
                                : ", failed tissue keeps its pressure in compression");
    }
    if (solver.subcycles_projectile() && static_cast<int>(b) == solver.projectile())
      line << ", subcycled: substeps of its own CFL step inside the scene's step, leading "
              "the contact";
    directory.log(line.str());
  }
  if (const std::string hold = rigid_hold_scene_line(solver); !hold.empty())
    directory.log(hold);
  std::ostringstream contact;
  contact << "  contact: ";
  if (solver.uses_contact() && scene.contact.enabled)
    contact << "multi-velocity field at nodes shared by bodies, friction "
            << scene.contact.friction_coefficient;
  else if (solver.uses_contact())
    contact << "disabled: the bodies share one velocity field (no-slip)";
  else
    contact << "none (one body): no contact pass";
  directory.log(contact.str());
}

std::string MpmStepper::progress() const
{
  return std::to_string(n_points_at_start + solver.split_points() - solver.removed_points()) +
         " points";
}

double MpmStepper::energy_balance_error() const
{
  return analysis::mpm_balance_error(solver, solver.diagnostics());
}

std::string MpmStepper::energy_error_causes() const
{
  std::string causes =
    "a Time/CFL too large (the contact's and the fixed or roller faces' losses, booked as "
    "dissipated_contact_J and dissipated_supports_J, close only as the step shrinks), "
    "bodies driven into each other or into a fixed face (a rigid body against a prescribed "
    "one), or no-slip contact (Contact/Friction coefficient = -1) between fast bodies";
  if (solver.background_grid().axisymmetric())
    causes += "; in axisymmetry, the axis's take (the x- face's share of dissipated_supports_J), "
              "whose booking is least exact where few cells span the projectile (the BB in "
              "gelatin: under 9 cells across, docs/validation.md)";
  return causes;
}

std::string MpmStepper::blow_up_remedy() const
{
  return "a smaller Time/CFL (restart from the last checkpoint with it), or a finer Grid/Cell "
         "size where points move more than a cell per step";
}

std::vector<std::string> MpmStepper::history_columns() const { return mpm_history_columns(); }

std::vector<double> MpmStepper::history_row() const
{
  return mpm_history_row(solver, solver.diagnostics());
}

std::vector<std::string> MpmStepper::final_warnings() const { return mpm_final_warnings(solver); }

std::vector<std::string> MpmStepper::events()
{
  std::vector<std::string> lines;
  for (const std::string& line : {rigid_hold_release_event(solver, hold_release_reported),
                                  rigid_rotation_event(solver, rotation_reported)})
    if (!line.empty())
      lines.push_back(line);
  return lines;
}

nlohmann::json MpmStepper::summary(const analysis::RunTotals& run) const
{
  analysis::RunTotals totals = run;
  totals.projectile_initial_speed = projectile.speed;
  totals.projectile_initial_kinetic_energy = projectile.kinetic_energy;
  analysis::WoundSample wound = analysis::collect_wound_sample(solver); // collective
  analysis::complete_by_mirrors(wound, solver.mirror_planes());
  const mpm::SceneDiagnostics final_state = solver.diagnostics();
  const std::array<mpm::Vector3, 6> supports = solver.support_impulses(); // collective
  const mpm::RankGroup& ranks = solver.rank_group();
  totals.mpi_bytes_sent = ranks.sum(ranks.bytes_sent());
  if (ranks.rank() != 0)
    return {};
  nlohmann::json j = analysis::mpm_summary(solver, totals, wound, final_state, supports);
  j["method"] = "MPM";
  return j;
}

std::string MpmStepper::final_report(const nlohmann::json& summary) const
{
  std::ostringstream o;
  o << std::setprecision(4) << "done: " << solver.step_count() << " steps to t = " << solver.time()
    << " s in " << summary["wall_seconds"].get<double>() << " s wall, "
    << summary["particle_steps_per_second"].get<double>() << " point-steps/s; phases (s): "
    << phase_report(solver.phase_times()) << "\n";
  o << "energy balance error " << summary["energy"]["balance_error"].get<double>()
    << "; failed points: matrix " << summary["failed"]["matrix"] << ", fiber "
    << summary["failed"]["fiber"] << ", total " << summary["failed"]["total"];
  if (solver.projectile() >= 0)
  {
    o << bullet_report(summary);
    o << projectile_note(solver);
  }
  o << unresolved_wound_report(summary) << unresolved_penetration_report(summary);
  return o.str();
}

std::string phase_report(const mpm::PhaseTimes& t)
{
  std::ostringstream o;
  o << std::setprecision(4) << "time step " << t.time_step << ", particle-to-grid "
    << t.particle_to_grid << ", grid update " << t.grid_update << ", contact " << t.contact
    << ", grid-to-particle " << t.grid_to_particle;
  if (t.nonlocal_failure > 0.0)
    o << ", nonlocal failure " << t.nonlocal_failure;
  o << ", stress " << t.stress_update;
  if (t.projectile_substeps > 0.0)
    o << ", projectile substeps " << t.projectile_substeps;
  o << ", checks " << t.checks_and_sorting;
  return o.str();
}

std::string elastic_projectile_note(const double substep_seconds, const double run_seconds,
                                    const double peak_von_mises_over_yield,
                                    const std::string& projectile_material)
{
  if (!(run_seconds > 0.0) || substep_seconds <= 0.5 * run_seconds ||
      !(peak_von_mises_over_yield < 0.1))
    return {};
  std::ostringstream o;
  o << std::setprecision(2) << "note: the projectile stayed elastic (peak von Mises "
    << peak_von_mises_over_yield << " of its yield stress) and its own substeps took "
    << std::setprecision(3) << 100.0 * substep_seconds / run_seconds
    << " % of the run; where its deformation does not matter, 'Material " << projectile_material
    << "/Model = rigid' spares them (the paper's isotropic 50 m/s scene: the same wound in 43 % "
       "of the time, docs/paper_results.md)";
  return o.str();
}

std::string projectile_note(const mpm::Solver& solver)
{
  const int b = solver.projectile();
  if (b < 0)
    return {};
  const auto body = static_cast<std::size_t>(b);
  const std::string note =
    elastic_projectile_note(solver.phase_times().projectile_substeps, solver.phase_times().total(),
                            solver.peak_von_mises_over_yield()[body],
                            solver.scene().bodies[body].material);
  const std::string hold = rigid_hold_final_note(solver);
  return (note.empty() ? note : "\n" + note) + (hold.empty() ? hold : "\n" + hold);
}

std::string unresolved_wound_report(const nlohmann::json& summary)
{
  const auto it = summary.find("wound_resolution");
  if (it == summary.end() || (*it)["unresolved"].empty())
    return "";
  std::string names;
  for (const auto& name : (*it)["unresolved"])
    names += (names.empty() ? "" : ", ") + name.get<std::string>();
  return "\nwound figures not resolved at this cell (summary.json wound_resolution): " + names;
}

std::string unresolved_penetration_report(const nlohmann::json& summary)
{
  const auto it = summary.find("penetration");
  if (it == summary.end() || !it->value("stopped", false) || !it->contains("resolution"))
    return "";
  const nlohmann::json& resolution = (*it)["resolution"];
  if (resolution.value("resolved", true))
    return "";
  return "\npenetration depth not resolved at this cell (summary.json penetration.resolution): " +
         resolution.value("reason", std::string());
}

std::string bullet_report(const nlohmann::json& summary)
{
  const nlohmann::json& bullet = summary["bullet"];
  std::ostringstream o;
  if (bullet.value("exited", false))
  {
    o << "; bullet exit velocity " << bullet["exit_velocity_m_s"].get<double>() << " m/s";
    if (bullet.value("fate", "") != "left the target through its far side")
      o << " (it " << bullet.value("fate", "") << ")";
  }
  else
    o << "; the bullet has not left the target: " << bullet.value("fate", "still inside it")
      << " (velocity now " << bullet["velocity_now_m_s"].get<double>() << " m/s)";
  return o.str();
}
} // namespace vulnus::simulator
