// Material-point driver: homogeneous deformation histories, CSV input/output, built-in paths.
#include "materials/point_driver.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace vulnus::materials
{
const char* const deformation_csv_header = "F11,F12,F13,F21,F22,F23,F31,F32,F33";
const char* const response_csv_header = "step,J,fiber_stretch,sigma_xx,sigma_yy,sigma_zz,"
                                        "sigma_xy,sigma_yz,sigma_xz,energy_density,failure";

namespace
{
std::string trimmed(const std::string& text)
{
  const auto begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos)
    return "";
  const auto end = text.find_last_not_of(" \t\r");
  return text.substr(begin, end - begin + 1);
}

std::vector<std::string> split_fields(const std::string& line)
{
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, ','))
    fields.push_back(trimmed(field));
  if (!line.empty() && line.back() == ',')
    fields.push_back("");
  return fields;
}

std::string header_without_spaces(const std::string& line)
{
  std::string result;
  for (const char c : line)
    if (c != ' ' && c != '\t' && c != '\r')
      result += c;
  return result;
}

[[noreturn]] void fail(const std::string& source, const std::size_t line,
                       const std::string& problem)
{
  throw std::invalid_argument(source + ": line " + std::to_string(line) + ": " + problem);
}

double parse_number(const std::string& text, const std::string& source, const std::size_t line,
                    const std::size_t column, const std::string& column_name)
{
  std::size_t used = 0;
  double value = 0.0;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value))
    fail(source, line,
         "column " + std::to_string(column) + " (" + column_name + "): '" + text +
             "' is not a finite number; give a decimal number such as 1.05");
  return value;
}

/// Reads the header and the rows of a CSV with the given exact header; calls row(fields,
/// line number) for every non-empty row after checking the field count.
template <class RowHandler>
void read_csv(std::istream& in, const std::string& source, const std::string& header,
              RowHandler&& row)
{
  std::string line;
  std::size_t line_number = 0;
  bool have_header = false;
  const std::vector<std::string> names = split_fields(header);
  while (std::getline(in, line))
  {
    ++line_number;
    if (trimmed(line).empty())
      continue;
    if (!have_header)
    {
      if (header_without_spaces(line) != header)
        fail(source, line_number,
             "header '" + trimmed(line) + "' is not the expected '" + header + "'");
      have_header = true;
      continue;
    }
    const std::vector<std::string> fields = split_fields(line);
    if (fields.size() != names.size())
      fail(source, line_number,
           "has " + std::to_string(fields.size()) + " columns, expected " +
               std::to_string(names.size()) + " (" + header + ")");
    row(fields, names, line_number);
  }
  if (!have_header)
    fail(source, line_number, "no header found; the first line must be '" + header + "'");
}

void write_number(std::ostream& out, const double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  out << buffer;
}
} // namespace

std::vector<PointDriverRow> drive_point(const Material& material,
                                        const std::vector<Tensor2>& history, const Vector3& a0,
                                        PointState state)
{
  const Vector3 fiber = a0.normalized();
  std::vector<PointDriverRow> rows;
  rows.reserve(history.size());
  for (std::size_t step = 0; step < history.size(); ++step)
  {
    const Tensor2& F = history[step];
    PointResponse response;
    try
    {
      material.update(F, fiber, state, response);
    }
    catch (const std::runtime_error& error)
    {
      throw std::runtime_error("step " + std::to_string(step) + ": " + error.what());
    }
    PointDriverRow row;
    row.step = step;
    row.J = F.determinant();
    row.fiber_stretch = (F * fiber).norm();
    row.cauchy_stress = response.cauchy_stress;
    row.energy_density = response.energy_density;
    row.failure = state.failure;
    rows.push_back(row);
  }
  return rows;
}

std::vector<Tensor2> read_deformation_csv(std::istream& in, const std::string& source)
{
  std::vector<Tensor2> history;
  read_csv(in, source, deformation_csv_header,
           [&](const std::vector<std::string>& fields, const std::vector<std::string>& names,
               const std::size_t line)
           {
             Tensor2 F;
             for (std::size_t c = 0; c < 9; ++c)
               F(c / 3, c % 3) = parse_number(fields[c], source, line, c + 1, names[c]);
             history.push_back(F);
           });
  return history;
}

std::vector<Tensor2> read_deformation_csv_file(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw std::invalid_argument(path + ": cannot open the deformation file; check the path");
  return read_deformation_csv(in, path);
}

void write_deformation_csv(std::ostream& out, const std::vector<Tensor2>& history)
{
  out << deformation_csv_header << '\n';
  for (const Tensor2& F : history)
  {
    for (int c = 0; c < 9; ++c)
    {
      if (c > 0)
        out << ',';
      write_number(out, F(c / 3, c % 3));
    }
    out << '\n';
  }
}

void write_response_csv(std::ostream& out, const std::vector<PointDriverRow>& rows)
{
  out << response_csv_header << '\n';
  for (const PointDriverRow& row : rows)
  {
    const Tensor2& s = row.cauchy_stress;
    out << row.step;
    for (const double value : {row.J, row.fiber_stretch, s(0, 0), s(1, 1), s(2, 2), s(0, 1),
                               s(1, 2), s(0, 2), row.energy_density})
    {
      out << ',';
      write_number(out, value);
    }
    out << ',' << row.failure << '\n';
  }
}

void write_response_csv_file(const std::string& path, const std::vector<PointDriverRow>& rows)
{
  std::ofstream out(path);
  if (!out)
    throw std::runtime_error(path + ": cannot open for writing; check the directory exists");
  write_response_csv(out, rows);
  if (!out)
    throw std::runtime_error(path + ": write failed; check free disk space");
}

std::vector<PointDriverRow> read_response_csv(std::istream& in, const std::string& source)
{
  std::vector<PointDriverRow> rows;
  read_csv(in, source, response_csv_header,
           [&](const std::vector<std::string>& fields, const std::vector<std::string>& names,
               const std::size_t line)
           {
             double v[11];
             for (std::size_t c = 0; c < 11; ++c)
               v[c] = parse_number(fields[c], source, line, c + 1, names[c]);
             PointDriverRow row;
             row.step = static_cast<std::size_t>(v[0]);
             row.J = v[1];
             row.fiber_stretch = v[2];
             row.cauchy_stress << v[3], v[6], v[8], v[6], v[4], v[7], v[8], v[7], v[5];
             row.energy_density = v[9];
             row.failure = static_cast<int>(v[10]);
             rows.push_back(row);
           });
  return rows;
}

std::vector<std::string> built_in_path_names()
{
  return {"uniaxial-fiber", "uniaxial-cross", "simple-shear", "equibiaxial", "volumetric"};
}

std::vector<Tensor2> built_in_path(const std::string& name, const double max_value,
                                   const int n_steps, const Vector3& a0)
{
  bool known = false;
  for (const std::string& candidate : built_in_path_names())
    known = known || candidate == name;
  if (!known)
  {
    std::string names;
    for (const std::string& candidate : built_in_path_names())
      names += (names.empty() ? "" : ", ") + candidate;
    throw std::invalid_argument("--path: unknown path '" + name + "'; choose one of " + names);
  }
  if (n_steps < 1)
    throw std::invalid_argument("--steps: must be at least 1 (got " + std::to_string(n_steps) +
                                "); give the number of steps");
  if (!std::isfinite(max_value) || (name != "simple-shear" && !(max_value > 0.0)))
    throw std::invalid_argument("--max: must be a finite positive stretch or J (got " +
                                std::to_string(max_value) + "); e.g. 1.5");
  if (!(a0.norm() > 0.0))
    throw std::invalid_argument("--fiber: must be a nonzero vector; e.g. 1,0,0");

  const Vector3 a = a0.normalized();
  int least_aligned = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(a[i]) < std::abs(a[least_aligned]))
      least_aligned = i;
  const Vector3 e = Vector3::Unit(least_aligned);
  const Vector3 m = (e - e.dot(a) * a).normalized();
  const Vector3 n = a.cross(m);
  const Tensor2 I = Tensor2::Identity();
  const Tensor2 aa = a * a.transpose();
  const Tensor2 mm = m * m.transpose();
  const Tensor2 nn = n * n.transpose();

  std::vector<Tensor2> history;
  for (int k = 0; k <= n_steps; ++k)
  {
    const double t = static_cast<double>(k) / n_steps;
    const double value = (name == "simple-shear") ? t * max_value : 1.0 + t * (max_value - 1.0);
    if (name == "uniaxial-fiber")
      history.push_back(value * aa + (I - aa) / std::sqrt(value));
    else if (name == "uniaxial-cross")
      history.push_back(value * mm + (I - mm) / std::sqrt(value));
    else if (name == "simple-shear")
      history.push_back(I + value * a * m.transpose());
    else if (name == "equibiaxial")
      history.push_back(value * (aa + mm) + nn / (value * value));
    else
      history.push_back(std::cbrt(value) * I);
  }
  return history;
}
} // namespace vulnus::materials
