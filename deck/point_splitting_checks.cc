// Checks of a deck that splits stretched points.
#include "deck/point_splitting_checks.h"

#include "deck/deck_checks.h"
#include "deck/deck_entries.h"
#include "deck/entry_checker.h"
#include "materials/material_registry.h"

namespace vulnus::deck
{
std::vector<std::string> check_point_splitting(const RunParameters& parameters,
                                               const EntryLocator& locator)
{
  const mpm::SceneParameters& s = parameters.scene;
  if (!(s.point_split_edge_cells > 0.0))
    return {};
  Checker out(locator);
  const std::string entry = "Grid/Point splitting";
  out.require(!s.axisymmetric, entry,
              "points split on a 3D grid (an axisymmetric point is a ring, which a split along "
              "its edge would not halve)",
              "set Grid/Dimension = 3, or Point splitting = 0");
  out.require(s.shape_function == mpm::ShapeFunction::linear, entry,
              "points split with Grid/Shape function = linear (a GIMP or CPDI point's domain is "
              "its body's, not its own)",
              "set Grid/Shape function = linear, or Point splitting = 0");
  for (const mpm::BodyParameters& body : s.bodies)
  {
    const mpm::NamedMaterial* material = scene::find_material(s, body.material);
    if (material == nullptr || material->parameters.model == "rigid" || body.is_projectile)
      continue; // the projectile's points do not split
    const double spacing = 1.0 / body.particles_per_cell;
    out.require(s.point_split_edge_cells > spacing, entry,
                "Body " + body.name + " seeds its points " + format_number(spacing) +
                  " cells apart, so every one of them would split at the first step",
                "set Point splitting above " + format_number(spacing) +
                  " cells (1.5 times the spacing splits where the material stretched by half)");
  }
  return out.messages;
}
} // namespace vulnus::deck
