// Pure-FE and hybrid checks of a deck, with the deck location of the entries involved.
#include "deck/method_checks.h"

#include "coupling/decomposition.h"
#include "materials/material_registry.h"

namespace vulnus::deck
{
namespace
{
bool body_is_rigid(const mpm::SceneParameters& scene, const mpm::BodyParameters& body)
{
  for (const mpm::NamedMaterial& m : scene.materials)
    if (m.name == body.material)
      return materials::create_material(m.parameters)->is_rigid();
  return false;
}

/// Locates a message `<path>, <path>: ...` at the first of its paths set in the deck (or on
/// the command line), else at `fallback`.
std::string locate(const EntryLocator& locator, const std::string& fallback,
                   const std::string& message)
{
  const std::string paths = message.substr(0, message.find(": "));
  std::size_t begin = 0;
  while (begin < paths.size())
  {
    std::size_t end = paths.find(", ", begin);
    if (end == std::string::npos)
      end = paths.size();
    const std::string path = paths.substr(begin, end - begin);
    if (path.find('/') != std::string::npos)
    {
      const std::string where = locator.where(path);
      if (where.find("(default value)") == std::string::npos)
        return where;
    }
    begin = end + 2;
  }
  return locator.where(fallback);
}

void add(std::vector<std::string>& out, const EntryLocator& locator, const std::string& fallback,
         const std::string& message)
{
  out.push_back(locate(locator, fallback, message) + ": " + message);
}

void check_fe_numerics(const fem::FeSceneParameters& fe, const EntryLocator& locator,
                       std::vector<std::string>& out)
{
  for (const std::string& p : fem::check_parameters(fe))
    add(out, locator, "Far field/Integrator", "Far field: " + p);
}
} // namespace

fem::FeSceneParameters pure_fe_scene(const RunParameters& parameters)
{
  return coupling::fe_region_of_body(parameters.scene, 0, parameters.far_field);
}

std::vector<std::string> check_method(const RunParameters& parameters, const EntryLocator& locator)
{
  std::vector<std::string> out;
  const mpm::SceneParameters& scene = parameters.scene;
  if (parameters.method == Method::fe)
  {
    if (parameters.hybrid.enabled)
      add(out, locator, "Hybrid/Enabled",
          "Scene/Method, Hybrid/Enabled: a pure-FE scene cannot be hybrid; set Method = MPM "
          "for a hybrid scene or Enabled = false");
    if (scene.bodies.size() != 1)
      add(out, locator, "Scene/Method",
          "Scene/Method, Scene/Bodies: a pure-FE scene has exactly one body (" +
            std::to_string(scene.bodies.size()) + " given); remove the others or use MPM");
    else
    {
      const mpm::BodyParameters& body = scene.bodies[0];
      if (body.shape != mpm::BodyShape::box || body.is_projectile || body_is_rigid(scene, body))
        add(out, locator, "Scene/Method",
            "Scene/Method: body '" + body.name +
              "' must be a deformable box and not a projectile to be meshed with finite "
              "elements; use Method = MPM");
      else if (body.initial_velocity.norm() != 0.0)
        add(out, locator, "Body " + body.name + "/Initial velocity",
            "Body " + body.name + "/Initial velocity: a pure-FE scene starts at rest; drive it "
            "with Far field/Load face instead");
      else
        check_fe_numerics(pure_fe_scene(parameters), locator, out);
    }
    return out;
  }
  if (!parameters.hybrid.enabled)
    return out;
  for (const std::string& p :
       coupling::check_decomposition(scene, parameters.hybrid, parameters.far_field))
    add(out, locator, "Hybrid/Enabled", p);
  if (out.empty())
    check_fe_numerics(
      coupling::decompose(scene, parameters.hybrid, parameters.far_field).fe, locator, out);
  return out;
}
} // namespace vulnus::deck
