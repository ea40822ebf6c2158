// Deck section `Scene`: the names of the materials and bodies. Read in a first pass, since
// they decide which `Material <name>` and `Body <name>` subsections exist.
#include "deck/deck_sections.h"

namespace vulnus::deck
{
void declare_scene_section(EntryTable& table)
{
  table.enter("Scene");
  table.declare("Materials", "tissue, bullet", name_list_pattern(),
                "Names of the materials; each gets a subsection `Material <name>`. The names "
                "tissue and bullet default to the paper's myocardium and bullet, other names "
                "to the tissue model with generic values.");
  table.declare("Bodies", "slab, bullet", name_list_pattern(),
                "Names of the bodies; each gets a subsection `Body <name>`. The names slab and "
                "bullet default to the paper's reference scene (50 x 10 x 50 mm slab, 9 mm "
                "bullet at 150 m/s along +y), other names to an empty box.");
  table.declare("Method", "MPM", dealii::Patterns::Selection("MPM|FE"),
                "MPM: material points everywhere (with Hybrid/Enabled the far field of the "
                "split body becomes finite elements); FE: finite elements only, for a scene of "
                "one deformable box body without projectile (settings in `Far field`).");
  table.leave();
}

SceneNames parse_scene_section(dealii::ParameterHandler& prm)
{
  SceneNames names;
  prm.enter_subsection("Scene");
  names.materials = split_list(prm.get("Materials"));
  names.bodies = split_list(prm.get("Bodies"));
  prm.leave_subsection();
  return names;
}
} // namespace vulnus::deck
