// Material-point driver: one point through a homogeneous deformation history, with CSV input
// and output and built-in deformation paths (backs the `vulnus point` command).
#pragma once

#include "materials/material.h"

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace vulnus::materials
{
/// One output row. Cauchy stress in Pa, energy per unit reference volume in J/m^3 (intact
/// parts only), fiber_stretch the total stretch |F a0|, failure the flag 0-3.
struct PointDriverRow
{
  std::size_t step = 0;
  double J = 1.0;
  double fiber_stretch = 1.0;
  Tensor2 cauchy_stress = Tensor2::Zero();
  double energy_density = 0.0;
  int failure = 0;
};

/// Exact CSV headers.
extern const char* const deformation_csv_header; ///< F11,F12,F13,F21,F22,F23,F31,F32,F33
extern const char* const response_csv_header;    ///< step,J,fiber_stretch,sigma_xx,...

/// Updates one point (initial state `state`) through the history in order; row k is the
/// response to history[k], step = k. a0 is normalized. A std::runtime_error of the material
/// (det F <= 0) is rethrown with the step number prefixed.
std::vector<PointDriverRow> drive_point(const Material& material,
                                        const std::vector<Tensor2>& history, const Vector3& a0,
                                        PointState state = PointState());

/// Reads a deformation history: header exactly deformation_csv_header (spaces and a trailing
/// CR tolerated), then one row of 9 numbers F11..F33 (row-major) per step; empty lines are
/// skipped. Throws std::invalid_argument naming `source`, the line and the column.
std::vector<Tensor2> read_deformation_csv(std::istream& in, const std::string& source = "input");
std::vector<Tensor2> read_deformation_csv_file(const std::string& path);

/// Writes a deformation history with deformation_csv_header (17 significant digits).
void write_deformation_csv(std::ostream& out, const std::vector<Tensor2>& history);

/// Writes rows with response_csv_header; stress columns xx yy zz xy yz xz; 17 digits, so
/// read_response_csv() gives back the same numbers.
void write_response_csv(std::ostream& out, const std::vector<PointDriverRow>& rows);
void write_response_csv_file(const std::string& path, const std::vector<PointDriverRow>& rows);

/// Reads what write_response_csv() writes (same error reporting as read_deformation_csv).
std::vector<PointDriverRow> read_response_csv(std::istream& in,
                                              const std::string& source = "input");

/// Names of the built-in paths: uniaxial-fiber, uniaxial-cross, simple-shear, equibiaxial,
/// volumetric.
std::vector<std::string> built_in_path_names();

/// Built-in path of n_steps + 1 deformation gradients, from F = I (row 0) to the maximum,
/// linear in the path parameter. With a0 the unit fiber, m a unit vector perpendicular to
/// a0 (from the coordinate axis least aligned with a0) and n = a0 x m:
///   uniaxial-fiber  F = l a0 a0 + l^{-1/2} (I - a0 a0), l up to max (isochoric)
///   uniaxial-cross  the same along m
///   simple-shear    F = I + g a0 m (fiber direction sheared across m), g up to max
///   equibiaxial     F = l (a0 a0 + m m) + l^{-2} n n, l up to max (isochoric)
///   volumetric      F = J^{1/3} I, J up to max
/// Throws std::invalid_argument for an unknown name, a stretch or J maximum that is not
/// positive, a non-finite maximum, or n_steps < 1.
std::vector<Tensor2> built_in_path(const std::string& name, double max_value, int n_steps,
                                   const Vector3& a0 = Vector3::UnitX());
} // namespace vulnus::materials
