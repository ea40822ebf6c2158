// Deck entries of the MPM scene's parameters.
#include "deck/scene_entries.h"

#include <map>

namespace vulnus::deck
{
std::string entry_of_scene_parameter(const std::string& name)
{
  static const std::map<std::string, std::string> entries = {
    {"cfl", "Time/CFL"},
    {"projectile_cfl", "Time/Projectile CFL"},
    {"min_time_step", "Time/Minimum time step"},
    {"max_time_step", "Time/Maximum time step"},
    {"end_time", "Time/End time"},
    {"artificial_viscosity_linear", "Time/Artificial viscosity linear"},
    {"artificial_viscosity_quadratic", "Time/Artificial viscosity quadratic"},
    {"domain_min", "Grid/Domain min"},
    {"domain_max", "Grid/Domain max"},
    {"cell_size", "Grid/Cell size"},
    {"remove_points_leaving_grid", "Grid/Points leaving the grid"},
    {"contact.friction_coefficient", "Contact/Friction coefficient"},
  };
  const std::string faces = "domain_faces.";
  if (name.rfind(faces, 0) == 0)
    return "Grid/Boundary conditions/" + name.substr(faces.size());
  const auto found = entries.find(name);
  return found != entries.end() ? found->second : name;
}
} // namespace vulnus::deck
