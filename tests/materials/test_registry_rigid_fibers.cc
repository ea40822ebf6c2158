// Tests of the material registry (names, documentation, creation, bad parameters), the rigid
// material and the fiber direction fields.
#include "materials/fiber_field.h"
#include "materials/material_registry.h"
#include "materials/rigid.h"

#include "material_test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vulnus::materials
{
namespace
{
/// The problems as the deck shows them: "<parameter>: <problem>; <remedy>".
std::vector<std::string> messages_of(const vulnus::materials::MaterialParameters& parameters)
{
  std::vector<std::string> messages;
  for (const vulnus::ParameterProblem& p : vulnus::materials::check_parameters(parameters))
    messages.push_back(p.parameters.front() + ": " + vulnus::describe(p));
  return messages;
}

bool contains(const std::vector<std::string>& messages, const std::string& text)
{
  return std::any_of(messages.begin(), messages.end(),
                     [&](const std::string& m) { return m.find(text) != std::string::npos; });
}

TEST(MaterialRegistry, AllModelsRegisterThemselves)
{
  const std::vector<std::string> names = registered_model_names();
  for (const char* name : {"transversely isotropic hyperelastic", "isotropic hyperelastic",
                           "elastic plastic", "rigid"})
  {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    EXPECT_FALSE(model_documentation(name).empty());
    MaterialParameters parameters;
    parameters.model = name;
    EXPECT_TRUE(check_parameters(parameters).empty()) << name;
    const std::unique_ptr<Material> material = create_material(parameters);
    ASSERT_TRUE(material);
    EXPECT_EQ(material->model_name(), name);
  }
  EXPECT_THROW(model_documentation("jelly"), std::invalid_argument);
}

TEST(MaterialRegistry, FibersFollowTheModel)
{
  MaterialParameters parameters;
  EXPECT_TRUE(create_material(parameters)->uses_fibers());
  parameters.tissue.with_fibers = false;
  EXPECT_FALSE(create_material(parameters)->uses_fibers());
  EXPECT_EQ(create_material(parameters)->model_name(), "isotropic hyperelastic");
  parameters.model = "rigid";
  EXPECT_TRUE(create_material(parameters)->is_rigid());
}

TEST(MaterialRegistry, BadTissueParametersAreRejectedWithMessages)
{
  MaterialParameters parameters;
  parameters.tissue.c1 = -2.0;
  parameters.tissue.c4 = 0.0;
  parameters.tissue.lambda_star = 0.9;
  parameters.tissue.bulk_modulus = 0.0;
  parameters.tissue.failure.matrix_shear_limit = -0.5;
  parameters.tissue.failure.fiber_stretch_limit = 1.0;
  const std::vector<std::string> messages = messages_of(parameters);
  EXPECT_EQ(messages.size(), 6u);
  for (const char* entry : {"c1: ", "c4: ", "Lambda star: ", "Bulk modulus: ",
                            "Matrix shear limit: ", "Fiber stretch limit: "})
    EXPECT_TRUE(contains(messages, entry)) << entry;
  for (const std::string& message : messages)
    EXPECT_NE(message.find("; "), std::string::npos) << message; // says what to do
  try
  {
    create_material(parameters);
    FAIL() << "create_material accepted bad parameters";
  }
  catch (const std::invalid_argument& error)
  {
    EXPECT_NE(std::string(error.what()).find("Lambda star: must be at least 1"), std::string::npos)
        << error.what();
  }
  // Without failure the limits are not checked; the isotropic model ignores fiber entries.
  parameters = MaterialParameters();
  parameters.model = "isotropic hyperelastic";
  parameters.tissue.c4 = -1.0;
  parameters.tissue.failure.enabled = false;
  parameters.tissue.failure.matrix_shear_limit = 0.0;
  EXPECT_TRUE(check_parameters(parameters).empty());
}

TEST(MaterialRegistry, BadElasticPlasticParametersAndUnknownModel)
{
  MaterialParameters parameters;
  parameters.model = "elastic plastic";
  parameters.elastic_plastic.yield_stress = 0.0;
  parameters.elastic_plastic.hardening_modulus = -1.0;
  parameters.elastic_plastic.shear_modulus = std::nan("");
  const std::vector<std::string> messages = messages_of(parameters);
  EXPECT_EQ(messages.size(), 3u);
  EXPECT_TRUE(contains(messages, "Yield stress: must be positive"));
  EXPECT_TRUE(contains(messages, "Hardening modulus: "));
  EXPECT_TRUE(contains(messages, "Shear modulus: "));
  EXPECT_THROW(create_material(parameters), std::invalid_argument);

  parameters.model = "steel";
  const std::vector<std::string> unknown = messages_of(parameters);
  ASSERT_EQ(unknown.size(), 1u);
  EXPECT_NE(unknown[0].find("Model: unknown material model 'steel'; choose one of"),
            std::string::npos);
  EXPECT_NE(unknown[0].find("'rigid'"), std::string::npos);
}

TEST(RigidMaterial, ZeroStressAndNoTimeStepLimit)
{
  const Rigid rigid;
  EXPECT_TRUE(rigid.is_rigid());
  PointState state;
  state.failure = matrix_failed;
  PointResponse response;
  response.cauchy_stress.setConstant(5.0);
  response.p_wave_modulus = 3.0;
  Tensor2 F = Tensor2::Identity();
  F(0, 1) = 0.3;
  rigid.update(1.2 * F, Vector3::UnitX(), state, response);
  EXPECT_EQ(response.cauchy_stress.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(response.p_wave_modulus, 0.0);
  EXPECT_EQ(response.energy_density, 0.0);
  EXPECT_EQ(state.failure, matrix_failed); // state untouched
  EXPECT_EQ(rigid.tangent(F, Vector3::UnitX(), state).cwiseAbs().maxCoeff(), 0.0);
}

TEST(FiberField, ConstantDirectionIsNormalized)
{
  FiberFieldParameters p;
  p.direction = Vector3(0.0, 0.0, 3.0);
  EXPECT_LT((fiber_direction(p, Vector3(1.0, 2.0, 3.0)) - Vector3::UnitZ()).norm(), 1e-15);
  p.direction = Vector3::Zero();
  EXPECT_THROW(fiber_direction(p, Vector3::Zero()), std::invalid_argument);
}

TEST(FiberField, RotatesHalfATurnThroughTheThicknessClockwise)
{
  // Paper slab: thickness 10 mm along y, fibers in the x-z plane, 180 degrees.
  FiberFieldParameters p;
  p.kind = FiberFieldParameters::Kind::rotating;
  p.direction = Vector3::UnitX();
  p.axis = Vector3::UnitY();
  p.start_coordinate = -0.005;
  p.end_coordinate = 0.005;
  p.total_angle_degrees = 180.0;
  const Vector3 entrance = fiber_direction(p, Vector3(0.01, -0.005, 0.02));
  const Vector3 middle = fiber_direction(p, Vector3(0.0, 0.0, 0.0));
  const Vector3 exit = fiber_direction(p, Vector3(-0.02, 0.005, 0.0));
  EXPECT_LT((entrance - Vector3::UnitX()).norm(), 1e-14);
  EXPECT_LT((exit + Vector3::UnitX()).norm(), 1e-14); // 180 degrees: reversed direction
  // Clockwise seen looking along +y (right-handed about +y): x turns towards -z.
  EXPECT_LT((middle - Vector3(0.0, 0.0, -1.0)).norm(), 1e-14);
  for (double y = -0.006; y <= 0.006; y += 0.0007)
  {
    const Vector3 a = fiber_direction(p, Vector3(0.0, y, 0.0));
    EXPECT_NEAR(a.norm(), 1.0, 1e-14);
    EXPECT_NEAR(a.y(), 0.0, 1e-14); // stays in the slab plane
    const double s = std::clamp((y + 0.005) / 0.01, 0.0, 1.0);
    EXPECT_NEAR(std::acos(std::clamp(a.x(), -1.0, 1.0)), s * M_PI, 1e-7);
  }
  // Clamped outside the slab.
  EXPECT_LT((fiber_direction(p, Vector3(0.0, 1.0, 0.0)) + Vector3::UnitX()).norm(), 1e-14);
  p.end_coordinate = p.start_coordinate;
  EXPECT_THROW(fiber_direction(p, Vector3::Zero()), std::invalid_argument);
}
} // namespace
} // namespace vulnus::materials
