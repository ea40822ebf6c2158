// The hybrid stepper: scene log, history rows with the interface ledger, summary.
#include "simulator/hybrid_stepper.h"

#include "analysis/wound_sample.h"
#include "fem/face_support.h"
#include "fem/tensor_conversion.h"
#include "io/run_directory.h"
#include "simulator/hybrid_history.h"
#include "simulator/rigid_hold_report.h"
#include "simulator/support_resolution.h"
#include "simulator/zone_end_guard.h"

#include <omp.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace vulnus::simulator
{
namespace
{
/// Collective: the far field's failed tissue joins the wound figures on the MPM lattice (the
/// far field carries matrix failure up to its conversion under `Adaptive zone failure =
/// total`, and the points of a cell are counted as its conversion would make them), as debris
/// where its cell carries a pressure alone, as for the MPM points.
void add_far_field_failures(analysis::WoundSample& wound, const coupling::HybridSolver& solver)
{
  std::vector<analysis::FailedPoint> points;
  if (wound.point_spacing > 0.0)
    for (const fem::FailedLatticePoint& p : solver.fe().failed_lattice_points(wound.point_spacing))
    {
      const bool debris =
        analysis::carries_no_deviatoric_stress(mpm::symmetric_part(fem::to_eigen(p.cell_stress)));
      points.push_back({mpm::Vector3(p.reference_position[0], p.reference_position[1],
                                     p.reference_position[2]),
                        p.reference_volume,
                        static_cast<std::uint8_t>(debris ? p.failure | analysis::debris_bit
                                                         : p.failure)});
    }
  analysis::add_failed_points(wound, solver.mpm().rank_group(), points);
}

const char* scheme_name(const coupling::CouplingScheme s)
{
  return s == coupling::CouplingScheme::same_step ? "same step" : "multi step";
}

const char* integrator_name(const fem::TimeIntegrator i)
{
  switch (i)
  {
  case fem::TimeIntegrator::central_difference:
    return "explicit central difference";
  case fem::TimeIntegrator::newmark:
    return "implicit Newmark";
  case fem::TimeIntegrator::generalized_alpha:
    return "implicit generalized alpha";
  }
  return "?";
}
} // namespace

HybridStepper::HybridStepper(const deck::RunParameters& parameters, const MPI_Comm communicator)
    : solver(coupling::decompose(parameters.scene, parameters.hybrid, parameters.far_field),
             communicator),
      projectile(projectile_start(solver.mpm())),
      initial_energy(hybrid_scene_energy(solver, solver.mpm().diagnostics(),
                                         solver.fe().diagnostics())),
      initial_momentum(solver.total_momentum())
{
}

void HybridStepper::log_scene(io::RunDirectory& directory) const
{
  const coupling::HybridScene& split = solver.scene();
  const std::size_t n_points = solver.mpm().n_points_all_ranks();
  std::ostringstream o;
  o << "hybrid scene: MPM zone (" << split.hybrid.zone_min[0] << ", " << split.hybrid.zone_min[1]
    << ", " << split.hybrid.zone_min[2] << ") to (" << split.hybrid.zone_max[0] << ", "
    << split.hybrid.zone_max[1] << ", " << split.hybrid.zone_max[2] << ") m: "
    << n_points << " points; FE far field: " << solver.fe().n_active_cells()
    << " cells, " << solver.fe().n_dofs() << " dofs, " << integrator_name(split.fe.integrator)
    << ", " << fem::integration_description(split.fe) << ", "
    << fem::shock_viscosity_description(split.fe) << "; " << solver.n_interface_nodes()
    << " shared interface nodes, scheme "
    << scheme_name(split.hybrid.scheme) << ", " << omp_get_max_threads() << " thread(s)"
    << mpm::describe_mirror_planes(solver.mpm().mirror_planes());
  if (split.hybrid.adaptive.enabled)
    o << "; adaptive zone: cells convert at " << split.hybrid.adaptive.threshold
      << " of the failure limits"
      << (split.hybrid.adaptive.total_failure_rule()
            ? " of a point's last intact part (the far field carries partial failure)"
            : "")
      << ", with " << split.hybrid.adaptive.margin_cells
      << " cells around them, within (" << split.limit_min[0] << ", " << split.limit_min[1]
      << ", " << split.limit_min[2] << ") to (" << split.limit_max[0] << ", "
      << split.limit_max[1] << ", " << split.limit_max[2] << ") m, checked every "
      << split.hybrid.adaptive.check_interval << " MPM steps";
  if (solver.balances_windows())
  {
    const std::size_t n_dofs = 3 * solver.n_interface_nodes();
    o << "; implicit windows " << (solver.dashpot_windows() ? "with a dashpot" : "balanced")
      << " (the far field's effective interface mass takes ";
    if (n_dofs <= solver.exact_balance_dofs())
      o << n_dofs << " far-field solves per window length)";
    else
      o << "at most " << 3 * coupling::HybridSolver::probe_period *
                             coupling::HybridSolver::probe_period *
                             coupling::HybridSolver::probe_period
        << " probing far-field solves per window length for its " << n_dofs << " dofs)";
    if (solver.dashpot_windows())
      o << ", windows of any length (a wave transit of the far field's smallest cell is "
        << solver.fe().shortest_wave_transit() << " s now)";
    else
      o << ", each window at most one wave transit of the far field's smallest cell ("
        << solver.fe().shortest_wave_transit() << " s now)";
  }
  const mpm::RankGroup& ranks = solver.mpm().rank_group();
  if (ranks.distributed())
    o << " on each of " << ranks.size() << " MPI ranks (MPM zone in slabs along axis "
      << solver.mpm().slabs().axis() << ", FE cells by deal.II's partition; "
      << solver.n_interface_nodes_across_ranks()
      << " interface nodes have their FE owner and MPM slab on different ranks)";
  directory.log(o.str());
  if (const std::string note = zone_end_note(split); !note.empty())
    directory.log("note: " + note);
  if (const std::string hold = rigid_hold_scene_line(solver.mpm()); !hold.empty())
    directory.log(hold);
}

std::string HybridStepper::progress() const
{
  std::ostringstream o;
  o << "FE step " << solver.ledger().fe_steps << ", interface energy error "
    << solver.ledger().energy_error() << " J";
  return o.str();
}

double HybridStepper::energy_balance_error() const
{
  const double energy = hybrid_scene_energy(solver, solver.mpm().diagnostics(),
                                            solver.fe().diagnostics());
  return analysis::relative_balance_error(energy, initial_energy);
}

std::string HybridStepper::energy_error_causes() const
{
  return "a Time/CFL too large (the fixed or roller faces' loss, dissipated_supports_J, closes "
         "only as the step shrinks), the interface exchange (Hybrid/Scheme; see the interface "
         "energy error in history.csv), or a projectile pushed into a fixed face or another "
         "rigid body";
}

std::vector<std::string> HybridStepper::check_validity(const bool final_check)
{
  check_zone_end(solver);
  return monitors.check(solver, initial_energy, final_check);
}

std::string HybridStepper::blow_up_remedy() const
{
  return "a smaller Time/CFL or Far field time step; an inverted or failed FE element means the "
         "wound reached the far field: enlarge Hybrid/Zone min and Zone max, or set "
         "Hybrid/Adaptive zone = true (or widen its reach)";
}

std::vector<std::string> HybridStepper::events()
{
  std::vector<std::string> lines;
  if (const std::string release = rigid_hold_release_event(solver.mpm(), hold_release_reported);
      !release.empty())
    lines.push_back(release);
  if (const std::string rotation = rigid_rotation_event(solver.mpm(), rotation_reported);
      !rotation.empty())
    lines.push_back(rotation);
  const std::vector<coupling::ZoneConversion>& done = solver.conversions();
  for (; conversions_logged < done.size(); ++conversions_logged)
  {
    const coupling::ZoneConversion& c = done[conversions_logged];
    std::ostringstream o;
    o << std::setprecision(4) << "adaptive zone: at t = " << c.time << " s (step " << c.mpm_step
      << ") the zone grew to (" << c.zone_min[0] << ", " << c.zone_min[1] << ", " << c.zone_min[2]
      << ") to (" << c.zone_max[0] << ", " << c.zone_max[1] << ", " << c.zone_max[2] << ") m: "
      << c.cells << " far-field cells became " << c.points << " points (" << c.volume * 1e6
      << " cm^3); energy change " << c.energy_after - c.energy_before << " J of "
      << c.energy_before << " J, momentum change " << (c.momentum_after - c.momentum_before).norm()
      << " kg m/s; asked for by " << c.flagged[static_cast<int>(coupling::ZoneCause::failure)]
      << " near failure, " << c.flagged[static_cast<int>(coupling::ZoneCause::interface_motion)]
      << " by interface motion, " << c.flagged[static_cast<int>(coupling::ZoneCause::distortion)]
      << " distorted";
    lines.push_back(o.str());
    if (conversions_logged + 1 == done.size() && solver.far_field_retired())
      lines.push_back("adaptive zone: the zone now holds the whole target; the far field has "
                      "no cell left and the run continues as pure MPM (the far field's support "
                      "impulses and energies up to now stay in the totals)");
  }
  return lines;
}

std::vector<std::string> HybridStepper::history_columns() const { return hybrid_history_columns(); }

std::vector<double> HybridStepper::history_row() const
{
  return hybrid_history_row(solver, initial_energy);
}

namespace
{
/// What asked for the zone's growth, by cause name.
nlohmann::json flagged_by_cause(const coupling::ZoneFlags& flagged)
{
  return {{"failure", flagged[static_cast<int>(coupling::ZoneCause::failure)]},
          {"interface_motion", flagged[static_cast<int>(coupling::ZoneCause::interface_motion)]},
          {"distortion", flagged[static_cast<int>(coupling::ZoneCause::distortion)]}};
}

/// The far field's cells on its fixed and roller faces against the grid's cell. Collective.
std::array<FaceResolution, 6> far_field_support_resolution(const coupling::HybridSolver& solver)
{
  const std::array<double, fem::n_slab_faces> coarsest = solver.fe().coarsest_cells_on_faces();
  std::array<double, 6> cells{};
  std::array<bool, 6> supported{};
  for (unsigned int f = 0; f < fem::n_slab_faces; ++f)
  {
    cells[f] = coarsest[f];
    supported[f] = fem::is_support(solver.scene().fe.faces[f].condition);
  }
  return support_resolution(cells, supported, solver.scene().fe.interface_cell_size);
}
} // namespace

std::vector<std::string> HybridStepper::final_warnings() const
{
  std::vector<std::string> warnings;
  const unsigned long long failed = solver.fe().diagnostics().n_failed_points; // collective
  if (failed > 0)
    warnings.push_back("*** " + std::to_string(failed) + " FE quadrature points failed" +
                       (solver.scene().hybrid.adaptive.total_failure_rule()
                          ? std::string(" totally")
                          : std::string()) +
                       ": the wound reached the far field, whose "
                       "answer is not the MPM zone's; enlarge Hybrid/Zone min and Zone max" +
                       std::string(solver.scene().hybrid.adaptive.enabled
                                     ? " or Hybrid/Adaptive zone reach, or lower the Adaptive "
                                       "zone threshold"
                                     : ", or set Hybrid/Adaptive zone = true"));
  if (solver.cells_beyond_limit() > 0)
    warnings.push_back("*** " + std::to_string(solver.cells_beyond_limit()) +
                       " far-field cells near failure or interface nodes moved too far lay at "
                       "or beyond the adaptive zone's reach at one check; widen Hybrid/Adaptive "
                       "zone reach");
  if (const unsigned long windows = solver.ledger().balance_unconverged_windows; windows > 0)
  {
    std::ostringstream o;
    o << "*** " << windows << " implicit window(s) ended before the far field's step met its "
      << "interface impulse (largest residual left " << solver.ledger().largest_balance_residual
      << " of the interface's momentum scale; what was left went into the next window): "
      << "shorten the windows (Hybrid/Substeps) or use Far field/Integrator = central difference";
    warnings.push_back(o.str());
  }
  // The interface may lose energy (windows dissipate what varies within them) but not make it.
  if (const double created = -solver.ledger().energy_error(); created > 0.01 * std::abs(initial_energy))
  {
    std::ostringstream o;
    o << "*** the coupling created " << created << " J at the interface, "
      << created / std::abs(initial_energy) << " of the scene's initial energy (the far field "
      << "received more work than the MPM side gave it): ";
    if (solver.scene().hybrid.window_coupling == coupling::WindowCoupling::dashpot)
      o << "dashpot windows dissipate only where the far field answers a window's impulse as "
           "its effective mass says (small strain over the window); use shorter windows "
           "(Hybrid/Substeps) or Hybrid/Window coupling = balanced";
    else
      o << "shorten the windows (Hybrid/Substeps) or lower Time/CFL";
    warnings.push_back(o.str());
  }
  const std::vector<std::string> coarse_supports = support_resolution_warnings(
    far_field_support_resolution(solver), solver.scene().fe.interface_cell_size);
  warnings.insert(warnings.end(), coarse_supports.begin(), coarse_supports.end());
  const std::vector<std::string> mpm_warnings = mpm_final_warnings(solver.mpm());
  warnings.insert(warnings.end(), mpm_warnings.begin(), mpm_warnings.end());
  return warnings;
}

nlohmann::json HybridStepper::summary(const analysis::RunTotals& run) const
{
  const mpm::Solver& mpm_side = solver.mpm();
  analysis::RunTotals totals = run;
  totals.projectile_initial_speed = projectile.speed;
  totals.projectile_initial_kinetic_energy = projectile.kinetic_energy;
  analysis::WoundSample wound = analysis::collect_wound_sample(mpm_side); // collective
  add_far_field_failures(wound, solver);                                  // collective
  analysis::complete_by_mirrors(wound, mpm_side.mirror_planes());
  const mpm::SceneDiagnostics m = mpm_side.diagnostics();
  const fem::FeDiagnostics fe = solver.fe().diagnostics();
  const std::array<mpm::Vector3, 6> supports = mpm_side.support_impulses(); // collective
  const Eigen::Vector3d momentum_now = solver.total_momentum();               // collective
  const std::array<FaceResolution, 6> resolution = far_field_support_resolution(solver);
  const mpm::RankGroup& ranks = mpm_side.rank_group();
  totals.mpi_bytes_sent = ranks.sum(ranks.bytes_sent());
  if (ranks.rank() != 0)
    return {};
  nlohmann::json summary = analysis::mpm_summary(mpm_side, totals, wound, m, supports);
  // One support ledger: each face's supports on both sides, the split kept in "hybrid".
  analysis::MomentumAudit audit;
  audit.initial = initial_momentum;
  audit.now = momentum_now; // both sides, and the impulse the next window gives back
  audit.removed = mpm_side.removed_momentum();
  audit.external = mpm_side.external_impulse();
  // Converted far-field material is not added from outside: it was the far field's.
  nlohmann::json mpm_split, fe_split;
  for (unsigned int f = 0; f < fem::n_slab_faces; ++f)
  {
    const mpm::Vector3 fe_impulse(fe.support_impulses[f][0], fe.support_impulses[f][1],
                                  fe.support_impulses[f][2]);
    const mpm::Vector3 total = supports[f] + fe_impulse;
    const char* const face = analysis::box_face_name(static_cast<int>(f));
    summary["supports"][face]["impulse_N_s"] = {total[0], total[1], total[2]};
    if (resolution[f].supported)
    {
      // The far field's cells there, and whether the impulse is within the resolution rule.
      summary["supports"][face]["far_field_cell_m"] = resolution[f].coarsest_cell;
      summary["supports"][face]["far_field_cell_over_grid_cell"] = resolution[f].over_grid_cell;
      summary["supports"][face]["far_field_resolves_impulse"] = resolution[f].resolved;
    }
    mpm_split[face] = {supports[f][0], supports[f][1], supports[f][2]};
    fe_split[face] = {fe_impulse[0], fe_impulse[1], fe_impulse[2]};
    audit.add_support(total);
  }
  summary["momentum_audit"] = analysis::momentum_audit_json(audit);
  const Eigen::Vector3d fe_momentum(fe.momentum[0], fe.momentum[1], fe.momentum[2]);
  summary["target"]["momentum_kg_m_s"] = {
    summary["target"]["momentum_kg_m_s"][0].get<double>() + fe_momentum[0],
    summary["target"]["momentum_kg_m_s"][1].get<double>() + fe_momentum[1],
    summary["target"]["momentum_kg_m_s"][2].get<double>() + fe_momentum[2]};
  summary["target"]["kinetic_energy_J"] =
    summary["target"]["kinetic_energy_J"].get<double>() + fe.kinetic_energy;
  const double energy = hybrid_scene_energy(solver, m, fe);
  const coupling::InterfaceLedger& ledger = solver.ledger();
  const coupling::HybridScene& split = solver.scene();
  summary["method"] = "hybrid";
  summary["fe_cells"] = solver.fe().n_active_cells();
  summary["fe_failed_points"] = fe.n_failed_points;
  summary["energy"]["initial_J"] = initial_energy;
  summary["energy"]["kinetic_J"] = m.kinetic_energy + fe.kinetic_energy;
  summary["energy"]["strain_J"] = m.strain_energy + fe.strain_energy;
  summary["energy"]["dissipated_J"] = m.dissipated_energy + mpm_side.contact_dissipation() +
                                      mpm_side.support_dissipation() + fe.dissipated_energy;
  summary["energy"]["balance_error"] =
    analysis::relative_balance_error(energy, initial_energy);
  summary["hybrid"] = {{"scheme", scheme_name(split.hybrid.scheme)},
                       {"fe_integrator", integrator_name(split.fe.integrator)},
                       {"fe_integration", fem::integration_description(split.fe)},
                       {"fe_shock_viscosity", {split.fe.shock_viscosity.linear,
                                               split.fe.shock_viscosity.quadratic}},
                       {"mpm_steps", ledger.mpm_steps},
                       {"fe_steps", ledger.fe_steps},
                       {"fe_time_s", solver.fe().time()},
                       {"interface_nodes", solver.n_interface_nodes()},
                       {"interface_nodes_across_ranks", solver.n_interface_nodes_across_ranks()},
                       {"fe_dofs", solver.fe().n_dofs()},
                       {"interface_mpm_work_J", ledger.mpm_work},
                       {"interface_fe_work_J", ledger.fe_work},
                       {"interface_energy_error_J", ledger.energy_error()},
                       {"interface_momentum_created_kg_m_s",
                        (ledger.mpm_impulse + ledger.fe_impulse + solver.impulse_in_transit()).norm()},
                       {"interface_impulse_in_transit_kg_m_s", solver.impulse_in_transit().norm()},
                       {"mpm_seconds", mpm_side.phase_times().total() - mpm_side.phase_times().coupling},
                       {"coupling_and_fe_seconds", mpm_side.phase_times().coupling}};
  if (split.fe.integrator == fem::TimeIntegrator::central_difference)
  {
    const fem::FePhaseTimes& fe_phases = solver.fe().explicit_phase_times();
    summary["hybrid"]["fe_phase_seconds"] = {
      {"cell_evaluation", fe_phases.internal_forces - fe_phases.assembly},
      {"assembly", fe_phases.assembly},
      {"rest_of_step", fe_phases.rest}};
  }
  if (solver.balances_windows())
    summary["hybrid"]["balance"] = {{"far_field_re_steps", ledger.balance_solves},
                                    {"unconverged_windows", ledger.balance_unconverged_windows},
                                    {"largest_residual_left", ledger.largest_balance_residual},
                                    {"effective_mass_matrices", ledger.balance_matrices},
                                    {"effective_mass_seconds", ledger.balance_matrix_seconds},
                                    {"windows_shortened_to_one_transit", ledger.windows_shortened},
                                    {"shortest_window_limit_s", ledger.shortest_window_limit},
                                    {"windows_halved", ledger.windows_halved},
                                    {"shortest_halved_window_s", ledger.dashpot_window_limit}};
  summary["hybrid"]["monitors"] = monitors.summary();
  summary["hybrid"]["far_field_retired"] = solver.far_field_retired();
  summary["hybrid"]["mpm_support_impulse_N_s"] = mpm_split;
  summary["hybrid"]["fe_support_impulse_N_s"] = fe_split;
  summary["hybrid"]["zone_min_m"] = solver.zone_min();
  summary["hybrid"]["zone_max_m"] = solver.zone_max();
  if (split.hybrid.adaptive.enabled)
  {
    nlohmann::json list = nlohmann::json::array();
    for (const coupling::ZoneConversion& c : solver.conversions())
      list.push_back({{"time_s", c.time},
                      {"mpm_step", c.mpm_step},
                      {"zone_min_m", c.zone_min},
                      {"zone_max_m", c.zone_max},
                      {"cells", c.cells},
                      {"points", c.points},
                      {"volume_m3", c.volume},
                      {"mass_kg", c.mass},
                      {"energy_before_J", c.energy_before},
                      {"energy_change_J", c.energy_after - c.energy_before},
                      {"momentum_change_kg_m_s", (c.momentum_after - c.momentum_before).norm()},
                      {"flagged_by_cause", flagged_by_cause(c.flagged)}});
    const bool total_rule = split.hybrid.adaptive.total_failure_rule();
    coupling::ZoneFlags flagged{};
    for (const coupling::ZoneConversion& c : solver.conversions())
      for (int k = 0; k < coupling::n_zone_causes; ++k)
        flagged[k] += c.flagged[k];
    summary["hybrid"]["adaptive_zone"] = {{"conversions", list},
                                          {"failure", total_rule ? "total" : "any"},
                                          {"flagged_by_cause", flagged_by_cause(flagged)},
                                          {"time_averaged_zone_fraction",
                                           solver.time_averaged_zone_fraction()},
                                          {"converted_volume_m3", solver.converted_volume()},
                                          {"energy_change_J", solver.conversion_energy_change()},
                                          {"cells_beyond_reach", solver.cells_beyond_limit()},
                                          {"check_seconds", solver.zone_check_seconds()},
                                          {"conversion_seconds", solver.zone_conversion_seconds()},
                                          {"limit_min_m", split.limit_min},
                                          {"limit_max_m", split.limit_max}};
  }
  return summary;
}

std::string HybridStepper::final_report(const nlohmann::json& summary) const
{
  const mpm::Solver& mpm_side = solver.mpm();
  const coupling::InterfaceLedger& ledger = solver.ledger();
  std::ostringstream o;
  o << std::setprecision(4) << "done: " << mpm_side.step_count() << " MPM steps and "
    << ledger.fe_steps << " FE steps to t = " << solver.time() << " s in "
    << summary["wall_seconds"].get<double>() << " s wall (MPM "
    << summary["hybrid"]["mpm_seconds"].get<double>() << " s, FE and coupling "
    << mpm_side.phase_times().coupling << " s";
  if (ledger.windows_shortened > 0)
    o << ", " << ledger.windows_shortened
      << " implicit windows shortened to one wave transit of the far field's smallest cell ("
      << ledger.shortest_window_limit << " s at the shortest)";
  if (ledger.windows_halved > 0)
    o << ", dashpot windows halved " << ledger.windows_halved
      << " times where the far field could not take them or they created energy (to "
      << ledger.dashpot_window_limit << " s)";
  // A window steps the far field to its end first: a run that stops inside one leaves the
  // far field's state (mesh output, supports, energies) at the window's end.
  if (!solver.far_field_retired() &&
      std::abs(solver.fe().time() - solver.time()) > 1e-9 * solver.time())
    o << "; the run stopped inside a coupling window: the far field stands at t = "
      << solver.fe().time() << " s";
  if (solver.scene().hybrid.adaptive.enabled)
    o << ", adaptive zone: " << solver.conversions().size() << " conversions "
      << solver.zone_conversion_seconds() << " s, checks " << solver.zone_check_seconds() << " s";
  o << "; MPM phases (s): "
    << phase_report(mpm_side.phase_times()) << ")\nenergy balance error "
    << summary["energy"]["balance_error"].get<double>() << ", interface energy error "
    << ledger.energy_error() << " J; failed points: matrix " << summary["failed"]["matrix"]
    << ", fiber " << summary["failed"]["fiber"] << ", total " << summary["failed"]["total"];
  if (mpm_side.projectile() >= 0)
  {
    o << bullet_report(summary);
    o << projectile_note(mpm_side);
  }
  o << unresolved_wound_report(summary) << unresolved_penetration_report(summary);
  return o.str();
}
} // namespace vulnus::simulator
