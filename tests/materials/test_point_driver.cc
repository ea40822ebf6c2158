// Tests of the material-point driver: built-in paths, CSV round trip, malformed CSV errors.
#include "materials/material_registry.h"
#include "materials/point_driver.h"

#include "material_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vulnus::materials
{
namespace
{
std::string error_of(const std::string& csv)
{
  std::istringstream in(csv);
  try
  {
    read_deformation_csv(in, "deformation.csv");
  }
  catch (const std::invalid_argument& error)
  {
    return error.what();
  }
  return "";
}

TEST(PointDriver, BuiltInPathsHaveTheAdvertisedKinematics)
{
  const Vector3 a0 = Vector3(1.0, 1.0, 0.0).normalized();
  const auto fiber = built_in_path("uniaxial-fiber", 1.3, 10, a0);
  ASSERT_EQ(fiber.size(), 11u);
  EXPECT_LT((fiber.front() - Tensor2::Identity()).norm(), 1e-15);
  EXPECT_NEAR((fiber.back() * a0).norm(), 1.3, 1e-14);
  EXPECT_NEAR(fiber.back().determinant(), 1.0, 1e-14);
  const auto cross = built_in_path("uniaxial-cross", 1.3, 4, a0);
  EXPECT_NEAR((cross.back() * a0).norm(), 1.0 / std::sqrt(1.3), 1e-14);
  const auto shear = built_in_path("simple-shear", 0.5, 5, a0);
  EXPECT_NEAR(shear.back().determinant(), 1.0, 1e-14);
  EXPECT_NEAR((shear.back() - Tensor2::Identity()).norm(), 0.5, 1e-14);
  const auto biaxial = built_in_path("equibiaxial", 1.2, 3, a0);
  EXPECT_NEAR((biaxial.back() * a0).norm(), 1.2, 1e-14);
  EXPECT_NEAR(biaxial.back().determinant(), 1.0, 1e-14);
  const auto volumetric = built_in_path("volumetric", 2.0, 8, a0);
  EXPECT_NEAR(volumetric.back().determinant(), 2.0, 1e-14);
  EXPECT_THROW(built_in_path("twist", 1.2, 3, a0), std::invalid_argument);
  EXPECT_THROW(built_in_path("volumetric", -1.0, 3, a0), std::invalid_argument);
  EXPECT_THROW(built_in_path("volumetric", 2.0, 0, a0), std::invalid_argument);
}

TEST(PointDriver, DrivesTissueThroughFailureAlongTheFiber)
{
  MaterialParameters parameters;
  const auto tissue = create_material(parameters);
  const Vector3 a0 = Vector3::UnitZ();
  const auto rows = drive_point(*tissue, built_in_path("uniaxial-fiber", 1.5, 100, a0), a0);
  ASSERT_EQ(rows.size(), 101u);
  EXPECT_EQ(rows.front().failure, 0);
  EXPECT_EQ(rows.back().failure, 3);
  for (const PointDriverRow& row : rows)
  {
    EXPECT_NEAR(row.J, 1.0, 1e-13);
    const int expected =
        (row.fiber_stretch > 1.4 ? 2 : 0) | (row.fiber_stretch > 1.324717957244746 ? 1 : 0);
    EXPECT_EQ(row.failure, expected) << "stretch " << row.fiber_stretch;
    if (row.failure == 3)
    {
      EXPECT_LT(row.cauchy_stress.norm(), 1e-6); // Pa: only the debris pressure of J = 1 - 1e-16
    }
  }
  EXPECT_GT(rows[50].cauchy_stress(2, 2), 0.0); // tension along the fiber before failure
}

TEST(PointDriver, CsvRoundTrip)
{
  MaterialParameters parameters;
  parameters.model = "elastic plastic";
  const auto bullet = create_material(parameters);
  const auto history = built_in_path("simple-shear", 0.02, 7);
  std::stringstream deformation;
  write_deformation_csv(deformation, history);
  EXPECT_EQ(deformation.str().substr(0, deformation.str().find('\n')),
            "F11,F12,F13,F21,F22,F23,F31,F32,F33");
  const auto read_back = read_deformation_csv(deformation);
  ASSERT_EQ(read_back.size(), history.size());
  for (std::size_t k = 0; k < history.size(); ++k)
    EXPECT_EQ(read_back[k], history[k]);

  const auto rows = drive_point(*bullet, read_back, Vector3::UnitX());
  std::stringstream response;
  write_response_csv(response, rows);
  EXPECT_EQ(response.str().substr(0, response.str().find('\n')),
            "step,J,fiber_stretch,sigma_xx,sigma_yy,sigma_zz,sigma_xy,sigma_yz,sigma_xz,"
            "energy_density,failure");
  const auto rows_back = read_response_csv(response);
  ASSERT_EQ(rows_back.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k)
  {
    EXPECT_EQ(rows_back[k].step, k);
    EXPECT_EQ(rows_back[k].J, rows[k].J);
    EXPECT_EQ(rows_back[k].cauchy_stress, rows[k].cauchy_stress);
    EXPECT_EQ(rows_back[k].energy_density, rows[k].energy_density);
  }
  EXPECT_GT(std::abs(rows.back().cauchy_stress(0, 1)), 1e8); // the bullet was loaded
}

TEST(PointDriver, MalformedCsvIsReportedWithLineAndColumn)
{
  const std::string header = "F11,F12,F13,F21,F22,F23,F31,F32,F33\n";
  EXPECT_EQ(error_of(header + "1,0,0,0,1,0,0,0,1\n1,0,0,0,x1,0,0,0,1\n"),
            "deformation.csv: line 3: column 5 (F22): 'x1' is not a finite number; give a "
            "decimal number such as 1.05");
  EXPECT_NE(error_of(header + "1,0,0,0,1,0,0,0\n").find("line 2: has 8 columns, expected 9"),
            std::string::npos);
  EXPECT_NE(error_of("F11,F12,F13\n1,0,0\n").find("line 1: header"), std::string::npos);
  EXPECT_NE(error_of("").find("no header"), std::string::npos);
  EXPECT_NE(error_of(header + "1,0,0,0,1,0,0,0,\n").find("column 9 (F33): ''"), std::string::npos);
  EXPECT_NE(error_of(header + "1,0,0,0,1,0,0,0,nan\n").find("column 9"), std::string::npos);
  // Tolerated: spaces, CR line ends, blank lines.
  EXPECT_EQ(error_of(" F11, F12,F13,F21,F22,F23,F31,F32,F33\r\n\n1, 0,0,0,1,0,0,0,1\r\n"), "");
}

TEST(PointDriver, InvertedStepIsReportedWithItsNumber)
{
  const auto tissue = create_material(MaterialParameters());
  std::vector<Tensor2> history{Tensor2::Identity(), -Tensor2::Identity()};
  try
  {
    drive_point(*tissue, history, Vector3::UnitX());
    FAIL() << "no error for det F < 0";
  }
  catch (const std::runtime_error& error)
  {
    EXPECT_EQ(std::string(error.what()).rfind("step 1: ", 0), 0u) << error.what();
  }
}
} // namespace
} // namespace vulnus::materials
