// Registry of material models by name: each model's .cc registers a factory, a parameter
// check and its documentation at static-initialization time (no central if/else factory).
// The library is linked whole-archive (materials/CMakeLists.txt) so every model registers.
#pragma once

#include "core/parameter_problem.h"

#include "materials/material.h"
#include "materials/material_parameters.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vulnus::materials
{
using MaterialFactory = std::function<std::unique_ptr<Material>(const MaterialParameters&)>;
/// Appends one message per problem, of the form "<entry>: <problem>; <what to do>".
using ParameterCheck =
    std::function<void(const MaterialParameters&, std::vector<ParameterProblem>& problems)>;

/// Registers a model; returns true so it can initialize a static. Throws std::logic_error
/// if the name is already taken.
bool register_material_model(const std::string& name, const std::string& documentation,
                             MaterialFactory factory, ParameterCheck check);

/// Names of all registered models, sorted.
std::vector<std::string> registered_model_names();

/// Documentation of a model (equation, entries, units); throws std::invalid_argument for an
/// unknown name.
std::string model_documentation(const std::string& name);

/// Problems with the parameters of the model named in parameters.model (empty when fine),
/// each naming its parameter as the model's documentation does ("c1", "Bulk modulus"; the
/// failure criterion's under "Failure/..."). An unknown model is reported under "Model".
std::vector<ParameterProblem> check_parameters(const MaterialParameters& parameters);

/// Checks the parameters and builds the model; throws std::invalid_argument with all
/// problems of check_parameters() ("<parameter>: <problem>; <remedy>"), one per line.
std::unique_ptr<Material> create_material(const MaterialParameters& parameters);
} // namespace vulnus::materials
