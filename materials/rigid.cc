// Registration of the rigid material.
#include "materials/rigid.h"

#include "materials/material_registry.h"

namespace vulnus::materials
{
namespace
{
const bool rigid_registered = register_material_model(
    "rigid",
    "Rigid body: no stress update, infinitely stiff, excluded from the time-step limit; it moves "
    "with prescribed or contact-driven rigid motion. The converged choice for a bullet that the "
    "elastic-plastic model reports elastic (von Mises / yield below 1). No entries.",
    [](const MaterialParameters&) -> std::unique_ptr<Material>
    { return std::make_unique<Rigid>(); },
    [](const MaterialParameters&, std::vector<ParameterProblem>&) {});
} // namespace
} // namespace vulnus::materials
