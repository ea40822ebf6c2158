// Registry of material models: name -> (documentation, factory, parameter check).
#include "materials/material_registry.h"

#include <map>
#include <stdexcept>

namespace vulnus::materials
{
namespace
{
struct ModelEntry
{
  std::string documentation;
  MaterialFactory factory;
  ParameterCheck check;
};

// Function-local static: safe against the static-initialization order of the model files.
std::map<std::string, ModelEntry>& registry()
{
  static std::map<std::string, ModelEntry> models;
  return models;
}

std::string joined_names()
{
  std::string names;
  for (const auto& [name, entry] : registry())
    names += (names.empty() ? "'" : ", '") + name + "'";
  return names;
}
} // namespace

bool register_material_model(const std::string& name, const std::string& documentation,
                             MaterialFactory factory, ParameterCheck check)
{
  const bool inserted =
      registry()
          .emplace(name, ModelEntry{documentation, std::move(factory), std::move(check)})
          .second;
  if (!inserted)
    throw std::logic_error("material model '" + name + "' registered twice");
  return true;
}

std::vector<std::string> registered_model_names()
{
  std::vector<std::string> names;
  for (const auto& [name, entry] : registry())
    names.push_back(name);
  return names;
}

std::string model_documentation(const std::string& name)
{
  const auto it = registry().find(name);
  if (it == registry().end())
    throw std::invalid_argument("Model: unknown material model '" + name + "'; choose one of " +
                                joined_names());
  return it->second.documentation;
}

std::vector<ParameterProblem> check_parameters(const MaterialParameters& parameters)
{
  std::vector<ParameterProblem> problems;
  const auto it = registry().find(parameters.model);
  if (it == registry().end())
  {
    problems.push_back({{"Model"}, "unknown material model '" + parameters.model + "'",
                        "choose one of " + joined_names()});
    return problems;
  }
  if (it->second.check)
    it->second.check(parameters, problems);
  return problems;
}

std::unique_ptr<Material> create_material(const MaterialParameters& parameters)
{
  const std::vector<ParameterProblem> problems = check_parameters(parameters);
  if (!problems.empty())
  {
    std::string joined;
    for (const ParameterProblem& problem : problems)
      joined += (joined.empty() ? "" : "\n") + problem.parameters.front() + ": " + describe(problem);
    throw std::invalid_argument(joined);
  }
  return registry().at(parameters.model).factory(parameters);
}
} // namespace vulnus::materials
