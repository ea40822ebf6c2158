// Deck section `Contact`: multi-velocity-field contact between bodies (Bardenhagen et al.).
#include "deck/deck_sections.h"

namespace vulnus::deck
{
void declare_contact_section(EntryTable& table)
{
  using namespace dealii;
  table.enter("Contact");
  table.declare("Enabled", "true", Patterns::Bool(),
                "Contact between bodies through separate velocity fields; false shares one "
                "velocity field (no-slip, bodies stick). A one-body scene does no contact work.");
  table.declare("Friction coefficient", "0.08", Patterns::Double(-1.0, 10.0),
                "Coulomb friction coefficient mu [-] (the paper: 0.08; 0: frictionless); a "
                "negative value means no-slip.");
  table.declare("Proximity distance", "0.8", Patterns::Double(0.0, 2.0),
                "Contact proximity check, in cell sizes [-]: two bodies interact at a node only "
                "when the distance along the contact normal between their mass centres seen "
                "from that node, after the step's approach, is at most this (the correction "
                "fades in over +-0.05 cells around it). 0 switches the "
                "check off (contact wherever both bodies reach a node and approach, up to a "
                "cell before their surfaces meet). Touching half-spaces under linear weights "
                "sit 2/3 of a cell apart.");
  table.declare("Rigid surface", "points", Patterns::Selection("points|exact"),
                "Where contact takes a rigid body's surface (a rigid material, or a projectile "
                "held rigid while elastic until the hold releases it: from there its points, "
                "as the log and summary.json say): points (its mass centre seen from each "
                "node, with the proximity distance above) or exact (its deck shape, sphere, box or "
                "cylinder, moved with it: a node engages where the other body's mass centre, "
                "less half that body's point spacing, reaches the shape after the step's "
                "approach, and the shape gives the normal; a rigid material's body then also weighs its "
                "shape's volume times its density, shared by its points; docs/validation.md).");
  table.declare("Criterion", "approach", Patterns::Selection("approach|approach or compression"),
                "Where bodies interact at a shared node: approach (only where they approach "
                "each other), or approach or compression (also where a body's surface is in "
                "compression, n . sigma n < 0 of its nodal stress, even while they separate: "
                "Uintah's friction_bard; one MPI rank; docs/uintah_side_by_side.md).");
  table.declare("Passes", "one", Patterns::Selection("one|two"),
                "one: contact corrects the velocities after the forces act. two: it also "
                "corrects the velocities projected from the points before the forces act, and "
                "the points' FLIP increments leave that first correction out (Uintah's "
                "friction_bard, OneOrTwoStep = 2). Not applied to a subcycled projectile's "
                "steps.");
  table.leave();
}

void parse_contact_section(dealii::ParameterHandler& prm, mpm::ContactParameters& contact)
{
  prm.enter_subsection("Contact");
  contact.enabled = prm.get_bool("Enabled");
  contact.friction_coefficient = prm.get_double("Friction coefficient");
  contact.proximity_distance = prm.get_double("Proximity distance");
  contact.exact_rigid_surface = prm.get("Rigid surface") == "exact";
  contact.hold_compressed_surfaces = prm.get("Criterion") == "approach or compression";
  contact.two_passes = prm.get("Passes") == "two";
  prm.leave_subsection();
}
} // namespace vulnus::deck
