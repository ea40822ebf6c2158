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
  table.leave();
}

void parse_contact_section(dealii::ParameterHandler& prm, mpm::ContactParameters& contact)
{
  prm.enter_subsection("Contact");
  contact.enabled = prm.get_bool("Enabled");
  contact.friction_coefficient = prm.get_double("Friction coefficient");
  prm.leave_subsection();
}
} // namespace vulnus::deck
