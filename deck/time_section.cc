// Deck section `Time`: end of the run and the explicit time step (CFL, bounds, viscosity).
#include "deck/deck_sections.h"

namespace vulnus::deck
{
void declare_time_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Time");
  table.declare("End time", "0.0003", Patterns::Double(0.0),
                "Simulated end time t_end [s]; must be > 0.");
  table.declare("CFL", "0.2", Patterns::Double(0.0, 1.0),
                "Courant number C in dt = C h / max(c + |v|), in (0, 1]; rigid bodies are "
                "excluded from the maximum. At 0.2 halving the step moves every wound figure "
                "of the paper scenes (rigid bullet) by at most 3 %; at 0.4 by up to 10 % "
                "(docs/converged_wound.md).");
  table.declare("Subcycle projectile", "true", Patterns::Bool(),
                "A deformable projectile advances in substeps of its own CFL step inside the "
                "scene's step, which then follows the target's wave speed. Contact is resolved "
                "once per scene step with the projectile leading (the target's nodes take its "
                "velocity, as a rigid body's; it takes their momentum as a load spread over its "
                "substeps): the wound then converges in the step and matches the rigid "
                "projectile's (docs/converged_wound.md section 13). It applies to a projectile "
                "whose impedance rho c is at least 10 times every other deformable body's; a "
                "softer one steps with the scene. false: the whole scene steps at the "
                "projectile's wave speed and contact treats it like the target.");
  table.declare("Projectile CFL", "0.4", Patterns::Double(0.0, 1.0),
                "Courant number of a subcycled projectile's substeps, h / max(c + |v|) times "
                "it, in [0, 1]; 0 uses Time/CFL. The projectile's elastic response enters the "
                "wound only through the contact, so its substeps may be longer than the "
                "target's steps need to be (docs/converged_wound.md, \"The projectile's own "
                "step\").");
  table.declare("Rigid projectile while elastic", "true", Patterns::Bool(),
                "A deformable projectile whose law has a yield stress (elastic plastic) moves "
                "as a rigid body, without stress update or substeps, while the contact keeps it "
                "far below yield: the contact pressure on it (the largest nodal contact force "
                "over h^2, averaged over the time it takes to cross a cell) stays below Rigid "
                "projectile stress limit times its yield stress, and the contact's moment would "
                "turn it by less than a tenth of a cell. It is not held at all when the "
                "acoustic impact pressure v Zp Zt / (Zp + Zt) on the stiffest target already "
                "exceeds that limit. At the first step a check fails it turns deformable for "
                "the rest of the run; the log and summary.json (bullet.rigid_hold) say when and "
                "why, or report the peaks against the limits (docs/uintah_side_by_side.md, "
                "\"The projectile's substeps\"). false: deformable from the start.");
  table.declare("Rigid projectile stress limit", "0.5", Patterns::Double(0.0, 1.0),
                "Fraction of its yield stress the averaged contact pressure on a projectile held "
                "rigid may reach (Rigid projectile while elastic), in (0, 1].");
  table.declare("Artificial viscosity linear", "0.06", Patterns::Double(0.0),
                "Linear bulk viscosity coefficient q1 [-] of the shock viscosity q = rho (q1 c h "
                "|tr D| + q2 h^2 (tr D)^2), acting in compression only (0: off). The default, "
                "the hydrocodes' usual pair 0.06 / 1.5, damps the ringing of the layer the "
                "bullet crushes ahead of its nose (docs/converged_wound.md); it vanishes as the "
                "cell size h goes to zero.");
  table.declare("Artificial viscosity quadratic", "1.5", Patterns::Double(0.0),
                "Quadratic bulk viscosity coefficient q2 [-] (0: off); see the linear one.");
  table.declare("Maximum time step", "1", Patterns::Double(0.0),
                "Cap dt_max on the time step [s]; must be > 0.");
  table.declare("Minimum time step", "1e-12", Patterns::Double(0.0),
                "Floor dt_min [s]: a step below it stops the run as a blow-up.");
  table.declare("Energy balance warning", "0.05", Patterns::Double(0.0),
                "Energy guard [-]: when |energy balance error| (energy neither present, "
                "dissipated nor removed, over the scene's initial energy) first exceeds this, "
                "the run warns in the log and summary.json with the step and the likely cause. "
                "Converged paper scenes stay below 0.015; 0 switches the warning off.");
  table.declare("Energy balance limit", "0.3", Patterns::Double(0.0),
                "Energy guard [-]: beyond this |energy balance error| the run stops as a "
                "blow-up and keeps its last good state; 0 switches the stop off.");
  table.declare("Stop when projectile exits", "true", Patterns::Bool(),
                "Stop once the projectile's tail has left every other body, before t_end.");
  table.declare("Stop when projectile stops", "false", Patterns::Bool(),
                "Stop once the projectile, its nose inside the target, has slowed to the "
                "Projectile stop speed along its flight or turned back, before t_end "
                "(penetration runs: summary.json's penetration.depth_m is then its depth at rest).");
  table.declare("Projectile stop speed", "1", Patterns::Double(0.0),
                "Speed [m/s] along the flight at or below which Stop when projectile stops ends "
                "the run; >= 0 (0: only when it turns back).");
  table.leave();
}

void parse_time_section(dealii::ParameterHandler& prm, mpm::SceneParameters& scene,
                        EnergyGuardParameters& energy_guard)
{
  prm.enter_subsection("Time");
  scene.end_time = prm.get_double("End time");
  scene.cfl = prm.get_double("CFL");
  scene.subcycle_projectile = prm.get_bool("Subcycle projectile");
  scene.projectile_cfl = prm.get_double("Projectile CFL");
  scene.rigid_projectile_while_elastic = prm.get_bool("Rigid projectile while elastic");
  scene.rigid_projectile_stress_limit = prm.get_double("Rigid projectile stress limit");
  scene.artificial_viscosity_linear = prm.get_double("Artificial viscosity linear");
  scene.artificial_viscosity_quadratic = prm.get_double("Artificial viscosity quadratic");
  scene.max_time_step = prm.get_double("Maximum time step");
  scene.min_time_step = prm.get_double("Minimum time step");
  scene.stop_when_projectile_exits = prm.get_bool("Stop when projectile exits");
  scene.stop_when_projectile_stops = prm.get_bool("Stop when projectile stops");
  scene.projectile_stop_speed = prm.get_double("Projectile stop speed");
  energy_guard.warning = prm.get_double("Energy balance warning");
  energy_guard.limit = prm.get_double("Energy balance limit");
  prm.leave_subsection();
}
} // namespace vulnus::deck
