// Deck section `Hybrid`: the MPM zone around the tract, the body it splits and the coupling
// scheme (docs/DESIGN.md section 6). A hybrid deck differs from its pure-MPM reference only here.
#include "deck/deck_sections.h"

namespace vulnus::deck
{
void declare_hybrid_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Hybrid");
  table.declare("Enabled", "false", Patterns::Bool(),
                "true: the split body is MPM inside the zone and finite elements outside, "
                "coupled on the zone surface every step.");
  table.declare("Zone min", "-0.012, 0, -0.012", point_pattern(),
                "Lower corner of the MPM zone [m], on grid nodes (Grid/Domain min + k h).");
  table.declare("Zone max", "0.012, 0.01, 0.012", point_pattern(),
                "Upper corner of the MPM zone [m], on grid nodes; the zone must hold the "
                "bullet path with its radius plus one cell, and the tissue that fails.");
  table.declare("Zone", "box", Patterns::Selection("box|around path"),
                "Where the MPM zone starts: box: Zone min to Zone max; around path: the "
                "projectile's path through the body with its radius plus one cell plus Zone "
                "margin on each side, widened to grid nodes.");
  table.declare("Zone margin", "0.002", Patterns::Double(0.0, 1.0),
                "Zone = around path: tissue kept around the projectile's radius plus one cell [m].");
  table.declare("Adaptive zone", "false", Patterns::Bool(),
                "true: far-field cells whose material nears failure become material points "
                "during the run; the zone box grows to hold them (docs/adaptive_zone.md).");
  table.declare("Adaptive zone threshold", "0.5", Patterns::Double(0.0, 1.0),
                "A cell converts when one of its quadrature points reaches this fraction of the "
                "failure limits (matrix shear / limit, (fiber stretch - 1) / (limit - 1)) or "
                "has failed, as Adaptive zone failure measures it.");
  table.declare("Adaptive zone failure", "any", Patterns::Selection("any|total"),
                "Which failure Adaptive zone threshold measures: any (a point nearing the "
                "failure of its matrix or of its fibers, or failed at all, converts its cell) or "
                "total (nearing the failure of both, a failed part counting as past its limit: the "
                "far field carries partial failure with the shared law and gives a cell up only "
                "near total failure, and its failed points, the FE warning and Stop when FE "
                "points fail count total failures only). total needs Adaptive zone = true and "
                "Adaptive zone distortion or corner Jacobian ratio > 0: a matrix-failed cell has "
                "no shear stiffness.");
  table.declare("Adaptive zone interface displacement", "0.1", Patterns::Double(0.0, 10.0),
                "The zone also grows where an interface node has moved this fraction of a "
                "grid cell, as Adaptive zone interface motion measures it (the validity monitor "
                "warns at 0.25 of its whole displacement; a window of the far field moves it by "
                "up to a few hundredths).");
  table.declare("Adaptive zone interface motion", "total", Patterns::Selection("total|non-affine"),
                "What of an interface node's motion Adaptive zone interface displacement bounds: "
                "total (its whole displacement) or non-affine (its departure from its far-field "
                "cell's best-fit rigid-plus-uniform-strain motion, which waves and rigid motion "
                "do not make).");
  table.declare("Adaptive zone distortion", "0", Patterns::Double(0.0, 10.0),
                "A far-field cell converts when its best-fit uniform stretch reaches "
                "ln(largest / smallest principal stretch) = this; 0: not checked.");
  table.declare("Adaptive zone corner Jacobian ratio", "0", Patterns::Double(0.0, 1.0),
                "A far-field cell converts when its smallest corner Jacobian falls below this "
                "fraction of its largest; 0: not checked.");
  table.declare("Adaptive zone margin", "2", Patterns::Integer(0, 1000),
                "Cells of tissue the grown zone keeps around a converting cell.");
  table.declare("Adaptive zone reach", "0.01", Patterns::Double(0.0, 10.0),
                "How far the zone may grow beyond its start on every side [m]; the far field "
                "has the grid's cells there.");
  table.declare("Adaptive zone check interval", "10", Patterns::Integer(1, 100000),
                "MPM steps between conversion checks; an FE window spans at most this many "
                "(multi step).");
  table.declare("Body", "", Patterns::Anything(),
                "Body split into zone and far field; empty: the only deformable box body "
                "that is not the projectile.");
  table.declare("Scheme", "multi step", Patterns::Selection("same step|multi step"),
                "same step: one time step, interface nodes shared (momentum exact); multi "
                "step: the far field steps over several MPM substeps (its own CFL step, or "
                "Far field/Time step when implicit).");
  table.declare("Substeps", "0", Patterns::Integer(0, 100000),
                "Multi step: at most this many MPM substeps per FE step (0: no limit; the FE "
                "step is then its own stable or deck step). An implicit far field's step is "
                "also kept within one wave transit of its smallest cell, beyond which the "
                "interface gains energy.");
  table.declare("Window coupling", "balanced", Patterns::Selection("balanced|dashpot"),
                "Multi step with an implicit far field: balanced (windows kept within one wave "
                "transit of the far field's smallest cell) or dashpot (the substeps see the far "
                "field's mean free interface velocity plus a dashpot of its effective interface "
                "mass; stable for windows of any length, dissipating what the far field's step "
                "cannot carry).");
  table.declare("Interface", "grid nodes", Patterns::Selection("grid nodes|following"),
                "Where the far field's interface nodes meet the MPM grid: grid nodes (each is "
                "the grid node it started on; the interface may move a quarter of a cell, which "
                "a monitor watches) or following (each is spread over the grid nodes around "
                "where it is now, like a material point, so the interface may move any "
                "distance; explicit far field only; docs/hybrid_interface.md).");
  table.declare("Stop when FE points fail", "true", Patterns::Bool(),
                "true: the run stops when a far-field quadrature point fails (totally, under "
                "Adaptive zone failure = total: the wound has reached the FE region, whose "
                "answer is then not the MPM zone's); false: it goes on and warns.");
  table.leave();
}

void parse_hybrid_section(dealii::ParameterHandler& prm, coupling::HybridParameters& hybrid)
{
  prm.enter_subsection("Hybrid");
  hybrid.enabled = prm.get_bool("Enabled");
  const Eigen::Vector3d lo = get_point(prm, "Zone min");
  const Eigen::Vector3d hi = get_point(prm, "Zone max");
  hybrid.zone_min = {lo[0], lo[1], lo[2]};
  hybrid.zone_max = {hi[0], hi[1], hi[2]};
  hybrid.body = prm.get("Body");
  hybrid.zone_start =
    prm.get("Zone") == "around path" ? coupling::ZoneStart::around_path : coupling::ZoneStart::box;
  hybrid.path_margin = prm.get_double("Zone margin");
  hybrid.adaptive.enabled = prm.get_bool("Adaptive zone");
  hybrid.adaptive.threshold = prm.get_double("Adaptive zone threshold");
  hybrid.adaptive.failure = prm.get("Adaptive zone failure") == "total"
                              ? fem::FailureProximity::total_failure
                              : fem::FailureProximity::any_failure;
  hybrid.adaptive.interface_displacement = prm.get_double("Adaptive zone interface displacement");
  hybrid.adaptive.interface_motion = prm.get("Adaptive zone interface motion") == "non-affine"
                                       ? coupling::InterfaceMotion::non_affine
                                       : coupling::InterfaceMotion::total;
  hybrid.adaptive.distortion = prm.get_double("Adaptive zone distortion");
  hybrid.adaptive.jacobian_ratio = prm.get_double("Adaptive zone corner Jacobian ratio");
  hybrid.adaptive.margin_cells = static_cast<unsigned int>(prm.get_integer("Adaptive zone margin"));
  hybrid.adaptive.reach = prm.get_double("Adaptive zone reach");
  hybrid.adaptive.check_interval =
    static_cast<unsigned int>(prm.get_integer("Adaptive zone check interval"));
  hybrid.scheme = prm.get("Scheme") == "same step" ? coupling::CouplingScheme::same_step
                                                    : coupling::CouplingScheme::multi_step;
  hybrid.substeps = static_cast<unsigned int>(prm.get_integer("Substeps"));
  hybrid.window_coupling = prm.get("Window coupling") == "dashpot"
                             ? coupling::WindowCoupling::dashpot
                             : coupling::WindowCoupling::balanced;
  hybrid.interface = prm.get("Interface") == "following"
                       ? coupling::InterfacePlacement::following
                       : coupling::InterfacePlacement::grid_nodes;
  hybrid.stop_when_fe_points_fail = prm.get_bool("Stop when FE points fail");
  prm.leave_subsection();
}
} // namespace vulnus::deck
