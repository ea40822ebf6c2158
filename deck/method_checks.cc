// Pure-FE and hybrid checks of a deck, with the deck location of the entries involved.
#include "deck/method_checks.h"

#include "deck/deck_checks.h"

#include "coupling/decomposition.h"
#include "fem/fe_scene_of_body.h"
#include "materials/material_registry.h"

#include <algorithm>
#include <map>

namespace vulnus::deck
{
namespace
{
/// The deck entry of a parameter a library named (check_decomposition, fem::check_parameters),
/// for a scene whose far field is meshed from body `body`.
std::string entry_of(std::string parameter, const std::string& body)
{
  static const std::map<std::string, std::string> entries = {
    {"body", "Hybrid/Body"},
    {"zone_min", "Hybrid/Zone min"},
    {"zone_max", "Hybrid/Zone max"},
    {"hole_min", "Hybrid/Zone min"},
    {"hole_max", "Hybrid/Zone max"},
    {"scheme", "Hybrid/Scheme"},
    {"window_coupling", "Hybrid/Window coupling"},
    {"interface", "Hybrid/Interface"},
    {"path_margin", "Hybrid/Zone margin"},
    {"adaptive.threshold", "Hybrid/Adaptive zone threshold"},
    {"adaptive.failure", "Hybrid/Adaptive zone failure"},
    {"adaptive.reach", "Hybrid/Adaptive zone reach"},
    {"adaptive.interface_motion", "Hybrid/Adaptive zone interface motion"},
    {"focus_min", "Hybrid/Adaptive zone reach"},
    {"focus_max", "Hybrid/Adaptive zone reach"},
    {"integrator", "Far field/Integrator"},
    {"degree", "Far field/Element degree"},
    {"one_point_integration", "Far field/Integration"},
    {"hourglass_coefficient", "Far field/Hourglass coefficient"},
    {"shock_viscosity", "Far field/Shock viscosity"},
    {"cfl", "Far field/CFL"},
    {"time_step", "Far field/Time step"},
    {"spectral_radius", "Far field/Spectral radius"},
    {"far_cell_size", "Far field/Far cell size"},
    {"grading_ratio", "Far field/Grading ratio"},
    {"supported_face_cells", "Far field/Supported face cells"},
    {"faces.profile.duration", "Far field/Load duration"},
    {"interface_cell_size", "Grid/Cell size"},
    {"end_time", "Time/End time"},
  };
  const std::string prefix = "far_field.";
  if (parameter.rfind(prefix, 0) == 0)
    parameter = parameter.substr(prefix.size());
  if (parameter == "slab_min")
    return "Body " + body + "/Box min";
  if (parameter == "slab_max")
    return "Body " + body + "/Box max";
  if (parameter == "density")
    return "Body " + body + "/Density";
  const auto found = entries.find(parameter);
  return found != entries.end() ? found->second : "Far field/Integrator";
}

/// Where the first of `paths` set in the deck (or on the command line) stands, else the
/// first path's default.
std::string where_first_set(const EntryLocator& locator, const std::vector<std::string>& paths)
{
  for (const std::string& path : paths)
    if (locator.is_set(path))
      return locator.where(path);
  return locator.where(paths.front());
}

/// "<where>: <entries>: <problem>; <remedy>".
std::string located(const EntryLocator& locator, const ParameterProblem& problem,
                    const std::string& body)
{
  std::vector<std::string> paths;
  for (const std::string& parameter : problem.parameters)
  {
    const std::string path = entry_of(parameter, body);
    if (std::find(paths.begin(), paths.end(), path) == paths.end())
      paths.push_back(path);
  }
  std::string joined;
  for (const std::string& path : paths)
    joined += (joined.empty() ? "" : ", ") + path;
  return where_first_set(locator, paths) + ": " + joined + ": " + describe(problem);
}

/// A check of this file: `message` names `paths` itself.
void add(std::vector<std::string>& out, const EntryLocator& locator,
         const std::vector<std::string>& paths, const std::string& message)
{
  out.push_back(where_first_set(locator, paths) + ": " + message);
}

void check_fe_numerics(const fem::FeSceneParameters& fe, const EntryLocator& locator,
                       const std::string& body, std::vector<std::string>& out)
{
  for (const ParameterProblem& p : fem::check_parameters(fe))
    out.push_back(located(locator, p, body));
}
} // namespace

fem::FeSceneParameters pure_fe_scene(const RunParameters& parameters)
{
  return fem::fe_scene_of_body(parameters.scene, 0, parameters.far_field);
}

std::vector<std::string> check_method(const RunParameters& parameters, const EntryLocator& locator)
{
  std::vector<std::string> out;
  const mpm::SceneParameters& scene = parameters.scene;
  if (parameters.method == Method::fe)
  {
    if (parameters.hybrid.enabled)
      add(out, locator, {"Scene/Method", "Hybrid/Enabled"},
          "Scene/Method, Hybrid/Enabled: a pure-FE scene cannot be hybrid; set Method = MPM "
          "for a hybrid scene or Enabled = false");
    if (scene.bodies.size() != 1)
      add(out, locator, {"Scene/Method", "Scene/Bodies"},
          "Scene/Method, Scene/Bodies: a pure-FE scene has exactly one body (" +
            std::to_string(scene.bodies.size()) + " given); remove the others or use MPM");
    else
    {
      const mpm::BodyParameters& body = scene.bodies[0];
      if (body.shape != mpm::BodyShape::box || body.is_projectile || body_is_rigid(scene, body))
        add(out, locator, {"Scene/Method"},
            "Scene/Method: body '" + body.name +
              "' must be a deformable box and not a projectile to be meshed with finite "
              "elements; use Method = MPM");
      else if (body.initial_velocity.norm() != 0.0)
        add(out, locator, {"Body " + body.name + "/Initial velocity"},
            "Body " + body.name + "/Initial velocity: a pure-FE scene starts at rest; drive it "
            "with Far field/Load face instead");
      else
        check_fe_numerics(pure_fe_scene(parameters), locator, body.name, out);
    }
    return out;
  }
  if (!parameters.hybrid.enabled)
    return out;
  if (scene.velocity_transfer == mpm::VelocityTransfer::xpic ||
      scene.velocity_transfer == mpm::VelocityTransfer::fmpm)
    add(out, locator, {"Grid/Velocity transfer", "Hybrid/Enabled"},
        std::string("Grid/Velocity transfer = ") +
          (scene.velocity_transfer == mpm::VelocityTransfer::xpic ? "XPIC" : "FMPM") +
          ": the hybrid's interface exchange assumes FLIP velocity increments at the shared "
          "nodes; use FLIP in a hybrid scene, or Hybrid/Enabled = false");
  const int split = coupling::split_body_index(scene, parameters.hybrid);
  const std::string body = split >= 0 ? scene.bodies[split].name : "";
  for (const ParameterProblem& p :
       coupling::check_decomposition(scene, parameters.hybrid, parameters.far_field))
    out.push_back(located(locator, p, body));
  if (out.empty())
    check_fe_numerics(coupling::decompose(scene, parameters.hybrid, parameters.far_field).fe,
                      locator, body, out);
  return out;
}
} // namespace vulnus::deck
