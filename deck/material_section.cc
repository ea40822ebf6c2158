// Deck subsections `Material <name>`: the model (a name from the material registry) and one
// subsection per model family with its parameters. Materials named `tissue` and `bullet`
// default to the paper's values (docs/DESIGN.md section 2).
#include "deck/deck_checks.h"
#include "deck/deck_sections.h"

#include "materials/material_registry.h"

#include <algorithm>

namespace vulnus::deck
{
namespace
{
using namespace dealii;

enum class ParameterGroup
{
  tissue_with_fibers,
  tissue_isotropic,
  elastic_plastic,
  none
};

ParameterGroup group_of(const std::string& model)
{
  if (model == "transversely isotropic hyperelastic")
    return ParameterGroup::tissue_with_fibers;
  if (model == "isotropic hyperelastic")
    return ParameterGroup::tissue_isotropic;
  if (model.find("plastic") != std::string::npos)
    return ParameterGroup::elastic_plastic;
  return ParameterGroup::none;
}

std::string selection_of(const std::vector<std::string>& names)
{
  std::string joined;
  for (const std::string& name : names)
    joined += (joined.empty() ? "" : "|") + name;
  return joined;
}

const char* shear_measure_names[3] = {"E1-E3", "(E1-E3)/2", "ln(l1/l3)"};

const char* volumetric_law_name(const materials::VolumetricLawKind kind)
{
  switch (kind)
  {
    case materials::VolumetricLawKind::hugoniot:
      return "Hugoniot";
    case materials::VolumetricLawKind::logarithmic:
      return "logarithmic";
    case materials::VolumetricLawKind::simo_hughes:
      break;
  }
  return "Simo-Hughes";
}

materials::VolumetricLawKind volumetric_law_of(const std::string& name)
{
  return name == "Hugoniot"      ? materials::VolumetricLawKind::hugoniot
         : name == "logarithmic" ? materials::VolumetricLawKind::logarithmic
                                 : materials::VolumetricLawKind::simo_hughes;
}

/// Volumetric law and Hugoniot slope; the tissue law offers no Simo-Hughes law.
void declare_volumetric_law(EntryTable& table, const materials::VolumetricLawKind kind,
                            const double slope, const bool with_simo_hughes)
{
  table.declare("Volumetric law", volumetric_law_name(kind),
                Patterns::Selection(with_simo_hughes ? "Simo-Hughes|logarithmic|Hugoniot"
                                                     : "logarithmic|Hugoniot"),
                std::string("Volumetric energy U(J): ") +
                    (with_simo_hughes ? "Simo-Hughes, U = K/2 [(J^2-1)/2 - ln J] (the "
                                        "bullet's); logarithmic, U = K/2 (ln J)^2; "
                                      : "logarithmic, U = K/2 (ln J)^2 (the paper's); ") +
                    "Hugoniot, compression on the linear shock Hugoniot Us = c0 + s up of "
                    "water-like tissue and gelatin (c0^2 = K / rho0, s = Hugoniot slope; "
                    "tension logarithmic; docs/volumetric_law.md).");
  table.declare("Hugoniot slope", format_number(slope), Patterns::Double(0.0),
                "Slope s of the shock Hugoniot Us = c0 + s up [-], Volumetric law = Hugoniot "
                "only; 0.5 to 4 (10 % gelatin: 2, Zochowski 2019).");
}

void declare_tissue(EntryTable& table, const materials::TissueParameters& d, const bool with_fibers)
{
  table.declare("c1", format_number(d.c1), Patterns::Double(0.0),
                "Mooney-Rivlin constant c1 [Pa]; > 0 (the paper: 2.1 kPa).");
  table.declare("c2", format_number(d.c2), Patterns::Double(0.0),
                "Mooney-Rivlin constant c2 [Pa]; >= 0 (the paper: 0).");
  if (with_fibers)
  {
    table.declare("c3", format_number(d.c3), Patterns::Double(0.0),
                  "Fiber toe-region stress scale c3 [Pa] (the paper: 0.14 kPa).");
    table.declare("c4", format_number(d.c4), Patterns::Double(0.0),
                  "Fiber uncrimping rate c4 [-] (the paper: 22).");
    table.declare("c5", format_number(d.c5), Patterns::Double(0.0),
                  "Modulus c5 of straightened fibers [Pa] (the paper: 100 kPa).");
    table.declare("Lambda star", format_number(d.lambda_star), Patterns::Double(1.0),
                  "Fiber stretch lambda* where fibers straighten [-]; >= 1 (the paper: 1.4).");
  }
  table.declare("Bulk modulus", format_number(d.bulk_modulus), Patterns::Double(0.0),
                "Bulk modulus K [Pa] of the volumetric energy (the paper: 200 kPa; water and "
                "soft tissue: about 2.2 GPa, inputs/water).");
  declare_volumetric_law(table, d.volumetric_law, d.hugoniot_slope, false);
  table.enter("Failure");
  table.declare("Enabled", d.failure.enabled ? "true" : "false", Patterns::Bool(),
                "Two-surface failure of matrix and fibers (paper eqs. 5-6).");
  table.declare("Shear measure", shear_measure_names[static_cast<int>(d.failure.shear_measure)],
                Patterns::Selection("E1-E3|(E1-E3)/2|ln(l1/l3)"),
                "Maximum shear strain measure compared with the matrix limit: E1-E3 of the "
                "principal Green strains, (E1-E3)/2, or ln(l1/l3) of the principal stretches.");
  table.declare("Matrix shear limit", format_number(d.failure.matrix_shear_limit),
                Patterns::Double(0.0),
                "Matrix failure limit gamma_crit [-]; > 0 (the paper: 0.5).");
  if (with_fibers)
    table.declare("Fiber stretch limit", format_number(d.failure.fiber_stretch_limit),
                  Patterns::Double(1.0),
                  "Fiber failure limit lambda_crit on the total fiber stretch [-]; > 1 (the "
                  "paper: 1.4, a fiber strain of 40 %).");
  table.declare("Regularization length", format_number(d.failure.regularization_length),
                Patterns::Double(0.0),
                "Nonlocal failure: radius l [m] over which the MPM points average both failure "
                "measures (bell weights (1 - r^2/l^2)^2 over the reference configuration) "
                "before comparing them with the limits, so the failed zone is at least about "
                "l wide whatever the cell size; 0: the paper's local criterion. FE points keep "
                "the local one. One MPI rank only (docs/mesh_objective_failure.md).");
  table.declare("Stress after failure",
                d.failure.stress_after_failure == materials::StressAfterFailure::zero ? "zero"
                                                                                       : "debris",
                Patterns::Selection("debris|zero"),
                "What a failed point carries. debris: a failed matrix keeps the volumetric "
                "pressure in compression and its fibers carry f a (x) a on the total stretch; "
                "total failure keeps the pressure in compression, so failed tissue is never "
                "crushed. zero: the paper's and Uintah's rule, a failed matrix annuls the "
                "matrix and volumetric stress (the fibers carry on as before), total failure "
                "annuls all; a failed point whose step would invert it becomes debris of its "
                "own volume (docs/uintah_side_by_side.md).");
  table.leave();
}

void parse_tissue(ParameterHandler& prm, materials::TissueParameters& t, const bool with_fibers)
{
  t.with_fibers = with_fibers;
  t.c1 = prm.get_double("c1");
  t.c2 = prm.get_double("c2");
  if (with_fibers)
  {
    t.c3 = prm.get_double("c3");
    t.c4 = prm.get_double("c4");
    t.c5 = prm.get_double("c5");
    t.lambda_star = prm.get_double("Lambda star");
  }
  else
    t.c3 = t.c5 = 0.0;
  t.bulk_modulus = prm.get_double("Bulk modulus");
  t.volumetric_law = volumetric_law_of(prm.get("Volumetric law"));
  t.hugoniot_slope = prm.get_double("Hugoniot slope");
  prm.enter_subsection("Failure");
  t.failure.enabled = prm.get_bool("Enabled");
  const std::string measure = prm.get("Shear measure");
  for (unsigned int m = 0; m < 3; ++m)
    if (measure == shear_measure_names[m])
      t.failure.shear_measure = static_cast<materials::ShearMeasure>(m);
  t.failure.matrix_shear_limit = prm.get_double("Matrix shear limit");
  if (with_fibers)
    t.failure.fiber_stretch_limit = prm.get_double("Fiber stretch limit");
  t.failure.regularization_length = prm.get_double("Regularization length");
  t.failure.stress_after_failure = prm.get("Stress after failure") == "zero"
                                     ? materials::StressAfterFailure::zero
                                     : materials::StressAfterFailure::debris;
  prm.leave_subsection();
}

void declare_elastic_plastic(EntryTable& table, const materials::ElasticPlasticParameters& d)
{
  table.declare("Bulk modulus", format_number(d.bulk_modulus), Patterns::Double(0.0),
                "Bulk modulus K [Pa]; > 0 (the paper's bullet: 117 GPa).");
  table.declare("Shear modulus", format_number(d.shear_modulus), Patterns::Double(0.0),
                "Shear modulus mu [Pa]; > 0 (the paper's bullet: 53.8 GPa).");
  table.declare("Yield stress", format_number(d.yield_stress), Patterns::Double(0.0),
                "Initial yield stress sigma_y [Pa]; > 0 (the paper's bullet: 422.6 MPa).");
  table.declare("Hardening modulus", format_number(d.hardening_modulus), Patterns::Double(0.0),
                "Linear isotropic hardening modulus H [Pa]; >= 0 (the paper's bullet: 53.8 MPa).");
  declare_volumetric_law(table, d.volumetric_law, d.hugoniot_slope, true);
  table.declare("Rate constant", format_number(d.rate_constant), Patterns::Double(0.0),
                "Cowper-Symonds D [1/s] of the flow stress (sigma_y + H alpha)(1 + (alpha_dot / "
                "D)^(1/q)), alpha_dot the equivalent plastic strain rate; 0: rate-independent "
                "(the default).");
  table.declare("Rate exponent", format_number(d.rate_exponent), Patterns::Double(0.0),
                "Cowper-Symonds exponent q [-]; 0.1 to 100 (1: a linear, viscous overstress).");
  table.declare("Failure plastic strain", format_number(d.failure_plastic_strain),
                Patterns::Double(0.0),
                "Equivalent plastic strain at which a point fails totally and becomes debris "
                "(pressure in compression only, counted as failed); 0: never (the default; 10 % "
                "gelatin: 0.9, Zochowski 2019).");
}

void parse_elastic_plastic(ParameterHandler& prm, materials::ElasticPlasticParameters& e)
{
  e.bulk_modulus = prm.get_double("Bulk modulus");
  e.shear_modulus = prm.get_double("Shear modulus");
  e.yield_stress = prm.get_double("Yield stress");
  e.hardening_modulus = prm.get_double("Hardening modulus");
  e.volumetric_law = volumetric_law_of(prm.get("Volumetric law"));
  e.hugoniot_slope = prm.get_double("Hugoniot slope");
  e.rate_constant = prm.get_double("Rate constant");
  e.rate_exponent = prm.get_double("Rate exponent");
  e.failure_plastic_strain = prm.get_double("Failure plastic strain");
}

std::string default_model(const std::string& material, const std::vector<std::string>& models)
{
  auto has = [&](const std::string& m)
  { return std::find(models.begin(), models.end(), m) != models.end(); };
  if (material == "bullet")
  {
    for (const std::string& m : models)
      if (group_of(m) == ParameterGroup::elastic_plastic)
        return m;
    if (has("rigid"))
      return "rigid";
  }
  if (has("transversely isotropic hyperelastic"))
    return "transversely isotropic hyperelastic";
  return models.empty() ? std::string() : models.front();
}
} // namespace

void declare_material_sections(EntryTable& table, const std::vector<std::string>& names)
{
  const std::vector<std::string> models = materials::registered_model_names();
  const materials::MaterialParameters defaults;
  for (const std::string& name : names)
  {
    table.enter("Material " + name);
    table.declare("Model", default_model(name, models), Patterns::Selection(selection_of(models)),
                  "Constitutive model of this material; its entries are in the subsection of "
                  "the same name (capitalized).");
    for (const std::string& model : models)
    {
      const ParameterGroup group = group_of(model);
      if (group == ParameterGroup::none)
        continue;
      table.enter(model_subsection(model));
      if (group == ParameterGroup::elastic_plastic)
        declare_elastic_plastic(table, defaults.elastic_plastic);
      else
        declare_tissue(table, defaults.tissue, group == ParameterGroup::tissue_with_fibers);
      table.leave();
    }
    table.leave();
  }
}

std::vector<mpm::NamedMaterial> parse_material_sections(ParameterHandler& prm,
                                                        const std::vector<std::string>& names)
{
  std::vector<mpm::NamedMaterial> result;
  for (const std::string& name : names)
  {
    prm.enter_subsection("Material " + name);
    mpm::NamedMaterial material;
    material.name = name;
    material.parameters.model = prm.get("Model");
    const ParameterGroup group = group_of(material.parameters.model);
    if (group != ParameterGroup::none)
    {
      prm.enter_subsection(model_subsection(material.parameters.model));
      if (group == ParameterGroup::elastic_plastic)
        parse_elastic_plastic(prm, material.parameters.elastic_plastic);
      else
        parse_tissue(prm, material.parameters.tissue, group == ParameterGroup::tissue_with_fibers);
      prm.leave_subsection();
    }
    prm.leave_subsection();
    result.push_back(material);
  }
  return result;
}
} // namespace vulnus::deck
