// Declaration and parsing of each deck section; one file per section (grid_section.cc, ...).
// Each `declare_*` declares its entries with patterns, defaults and documentation; each
// `parse_*` reads them (already validated against their patterns) into plain structs.
#pragma once

#include "deck/deck_entries.h"
#include "deck/run_parameters.h"

#include <string>
#include <vector>

namespace vulnus::deck
{
/// Names of the materials and bodies (section Scene): pass 1 of the two-pass reading.
struct SceneNames
{
  std::vector<std::string> materials;
  std::vector<std::string> bodies;
};
void declare_scene_section(EntryTable& table);
SceneNames parse_scene_section(dealii::ParameterHandler& prm);

void declare_grid_section(EntryTable& table);
void parse_grid_section(dealii::ParameterHandler& prm, mpm::SceneParameters& scene);

void declare_contact_section(EntryTable& table);
void parse_contact_section(dealii::ParameterHandler& prm, mpm::ContactParameters& contact);

void declare_time_section(EntryTable& table);
void parse_time_section(dealii::ParameterHandler& prm, mpm::SceneParameters& scene,
                        EnergyGuardParameters& energy_guard);

void declare_output_section(EntryTable& table);
void parse_output_section(dealii::ParameterHandler& prm, OutputParameters& output);

void declare_run_section(EntryTable& table);
void parse_run_section(dealii::ParameterHandler& prm, mpm::SceneParameters& scene);

/// `Scene/Method`, `subsection Far field` (FE numerics) and `subsection Hybrid`.
void declare_far_field_section(EntryTable& table);
void parse_far_field_section(dealii::ParameterHandler& prm, RunParameters& parameters);
void declare_hybrid_section(EntryTable& table);
void parse_hybrid_section(dealii::ParameterHandler& prm, coupling::HybridParameters& hybrid);

/// `subsection Material <name>` for each name.
void declare_material_sections(EntryTable& table, const std::vector<std::string>& names);
std::vector<mpm::NamedMaterial> parse_material_sections(dealii::ParameterHandler& prm,
                                                        const std::vector<std::string>& names);

/// `subsection Body <name>` for each name.
void declare_body_sections(EntryTable& table, const std::vector<std::string>& names);
std::vector<mpm::BodyParameters> parse_body_sections(dealii::ParameterHandler& prm,
                                                     const std::vector<std::string>& names);
} // namespace vulnus::deck
