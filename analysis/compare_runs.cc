// `vulnus compare`: summary.json side by side and the failure flags of shared points
// (plain HDF5 C API and nlohmann::json; no deal.II).
#include "analysis/compare_runs.h"

#include "analysis/slice_profiles.h"
#include "io/hdf5_handle.h"

#include <hdf5.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace vulnus::analysis
{
namespace
{
namespace fs = std::filesystem;

/// A missing or unreadable input: reported on `err`, exit status 2.
class CompareError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

constexpr double position_tolerance = 1e-7; // m, for matching reference positions
const char* const flag_names[4] = {"intact", "matrix", "fiber", "total"};

// ---------------------------------------------------------------------------------------------
// summary.json

struct Leaf
{
  std::string key;
  double value;
};

void flatten(const nlohmann::json& node, const std::string& key, std::vector<Leaf>& leaves)
{
  if (node.is_object())
    for (const auto& item : node.items())
      flatten(item.value(), key.empty() ? item.key() : key + "." + item.key(), leaves);
  else if (node.is_array())
    for (std::size_t i = 0; i < node.size(); ++i)
      flatten(node[i], key + "[" + std::to_string(i) + "]", leaves);
  else if (node.is_boolean())
    leaves.push_back({key, node.get<bool>() ? 1.0 : 0.0});
  else if (node.is_number())
    leaves.push_back({key, node.get<double>()});
}

void check_directory(const std::string& run)
{
  std::error_code error;
  if (!fs::is_directory(run, error))
    throw CompareError("'" + run + "' is not a run directory (it does not exist or is a file)");
}

nlohmann::json read_summary(const std::string& run)
{
  const fs::path path = fs::path(run) / "summary.json";
  std::ifstream in(path);
  if (!in)
    throw CompareError("cannot read '" + path.string() +
                       "' (missing or unreadable; did the run finish?)");
  try
  {
    return nlohmann::json::parse(in);
  }
  catch (const nlohmann::json::exception& error)
  {
    throw CompareError("'" + path.string() + "' is not valid JSON: " + error.what());
  }
}

std::string format_number(const double value, const int precision)
{
  std::ostringstream text;
  text << std::setprecision(precision) << value;
  return text.str();
}

using Row = std::array<std::string, 5>;

void print_table(const std::vector<Row>& rows, std::ostream& out)
{
  std::array<std::size_t, 5> width{};
  for (const Row& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c)
      width[c] = std::max(width[c], row[c].size());
  for (const Row& row : rows)
  {
    std::ostringstream line;
    line << std::left << std::setw(static_cast<int>(width[0])) << row[0] << std::right;
    for (std::size_t c = 1; c < row.size(); ++c)
      line << "  " << std::setw(static_cast<int>(width[c])) << row[c];
    std::string text = line.str();
    text.erase(text.find_last_not_of(' ') + 1);
    out << text << '\n';
  }
}

void compare_summaries(const nlohmann::json& a, const nlohmann::json& b, std::ostream& out)
{
  std::vector<Leaf> leaves_a, leaves_b;
  flatten(a, "", leaves_a);
  flatten(b, "", leaves_b);

  // Keys in A's order, then those only B has.
  std::vector<std::string> keys;
  std::map<std::string, double> value_a, value_b;
  for (const Leaf& leaf : leaves_a)
  {
    keys.push_back(leaf.key);
    value_a[leaf.key] = leaf.value;
  }
  for (const Leaf& leaf : leaves_b)
  {
    if (value_a.count(leaf.key) == 0)
      keys.push_back(leaf.key);
    value_b[leaf.key] = leaf.value;
  }

  std::vector<Row> rows{{"summary.json", "A", "B", "B - A", "(B - A)/|A|"}};
  unsigned int n_differ = 0, n_one_sided = 0;
  for (const std::string& key : keys)
  {
    const auto in_a = value_a.find(key), in_b = value_b.find(key);
    Row row{key, "-", "-", "", ""};
    if (in_a != value_a.end())
      row[1] = format_number(in_a->second, 10);
    if (in_b != value_b.end())
      row[2] = format_number(in_b->second, 10);
    if (in_a == value_a.end() || in_b == value_b.end())
    {
      ++n_one_sided;
      row[3] = "only in " + std::string(in_a == value_a.end() ? "B" : "A");
    }
    else
    {
      const double difference = in_b->second - in_a->second;
      n_differ += difference != 0.0 ? 1 : 0;
      row[3] = format_number(difference, 4);
      row[4] = difference == 0.0     ? "0"
               : in_a->second == 0.0 ? "inf"
                                     : format_number(difference / std::abs(in_a->second), 3);
    }
    rows.push_back(row);
  }
  print_table(rows, out);
  out << keys.size() << " numbers: " << n_differ << " differ, " << n_one_sided
      << " in one run only\n";
}

/// A numeric array of `summary[section][key]`, or nothing when it is missing or not numeric.
std::optional<std::vector<double>> numbers(const nlohmann::json& summary, const char* section,
                                           const char* key)
{
  if (!summary.contains(section) || !summary[section].contains(key) ||
      !summary[section][key].is_array())
    return std::nullopt;
  std::vector<double> values;
  for (const auto& value : summary[section][key])
  {
    if (!value.is_number())
      return std::nullopt;
    values.push_back(value.get<double>());
  }
  return values;
}

/// Runs at different cell sizes slice their tract differently (one cell per slice): B's tract
/// areas are then averaged over A's slices, so that tract.area_m2[i] compares the same depths.
void align_tract_slices(const nlohmann::json& a, nlohmann::json& b, std::ostream& out)
{
  const auto depth_a = numbers(a, "tract", "depth_m"), depth_b = numbers(b, "tract", "depth_m");
  const auto area_b = numbers(b, "tract", "area_m2");
  if (!depth_a || !depth_b || !area_b || depth_a->empty() || depth_b->empty() ||
      same_slices(*depth_a, *depth_b) || area_b->size() != depth_b->size())
    return;
  const auto rebinned = rebin_slices(*depth_b, *area_b, *depth_a);
  nlohmann::json areas = nlohmann::json::array(), depths = nlohmann::json::array();
  for (std::size_t i = 0; i < rebinned.size(); ++i)
  {
    areas.push_back(rebinned[i] ? nlohmann::json(*rebinned[i]) : nlohmann::json());
    depths.push_back(rebinned[i] ? nlohmann::json((*depth_a)[i]) : nlohmann::json());
  }
  b["tract"]["area_m2"] = areas;
  b["tract"]["depth_m"] = depths;
  const auto slicing = [](const std::vector<double>& depth)
  {
    return std::to_string(depth.size()) + " slices of " +
           format_number(1e3 * slice_thickness(depth), 4) + " mm";
  };
  out << "note: the runs slice the tract differently (A: " << slicing(*depth_a)
      << ", B: " << slicing(*depth_b)
      << "); B's tract.area_m2 below is its profile averaged over A's slices\n\n";
}

/// The entrance and exit wounds are the failed points of a layer below each face; runs that
/// measured them in layers of different depth (or before the depth was recorded: one cell)
/// compare different things, which the reader is told.
void note_face_layers(const nlohmann::json& a, const nlohmann::json& b, std::ostream& out)
{
  const auto layer = [](const nlohmann::json& s)
  {
    const auto it = s.find("wound_face_layer_m");
    return it != s.end() && it->is_number() ? format_number(1e3 * it->get<double>(), 4) + " mm"
                                            : std::string("one cell (run before the entry)");
  };
  const std::string layer_a = layer(a), layer_b = layer(b);
  if (layer_a != layer_b)
    out << "note: the runs measure the entrance and exit wounds in face layers of different "
           "depth (A: "
        << layer_a << ", B: " << layer_b
        << "); their face figures differ by that too (Output/Wound face layer)\n\n";
}

/// Linear interpolation of the curve (x increasing where it is sampled) at x; nothing outside.
std::optional<double> interpolate(const std::vector<double>& xs, const std::vector<double>& ys,
                                  const double x)
{
  for (std::size_t i = 1; i < xs.size(); ++i)
    if ((xs[i - 1] <= x && x <= xs[i]) && xs[i] > xs[i - 1])
      return ys[i - 1] + (ys[i] - ys[i - 1]) * (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return std::nullopt;
}

/// The velocity-depth curves are sampled at each run's own depths and the cavity profiles are
/// one cell per slice, so neither compares index by index: each run's curve is replaced by its
/// velocity at the same five depths (0, 1/4, ... 1 of the shallower run's deepest point), and
/// the per-slice cavity lists are left out (their largest value stays; plot-wound draws them).
void compact_penetration(nlohmann::json& a, nlohmann::json& b, std::ostream& out)
{
  const auto curve = [](const nlohmann::json& summary, const char* key)
  {
    std::vector<double> values;
    if (summary.contains("penetration") && summary["penetration"].contains("curve"))
      for (const auto& v : summary["penetration"]["curve"][key])
        values.push_back(v.is_number() ? v.get<double>() : std::nan(""));
    return values;
  };
  const std::vector<double> depth_a = curve(a, "depth_m"), depth_b = curve(b, "depth_m");
  const bool both_curves = !depth_a.empty() && !depth_b.empty();
  const double deepest = both_curves ? std::min(*std::max_element(depth_a.begin(), depth_a.end()),
                                                *std::max_element(depth_b.begin(), depth_b.end()))
                                     : 0.0;
  if (both_curves)
  {
    const std::vector<double> speed_a = curve(a, "velocity_m_s"), speed_b = curve(b, "velocity_m_s");
    for (const double fraction : {0.0, 0.25, 0.5, 0.75, 1.0})
    {
      char key[48];
      std::snprintf(key, sizeof(key), "velocity_m_s_at_depth_fraction_%.2f", fraction);
      for (auto [summary, depths, speeds] : {std::tie(a, depth_a, speed_a), std::tie(b, depth_b, speed_b)})
      {
        const std::optional<double> v = interpolate(depths, speeds, fraction * deepest);
        summary["penetration"][key] = v ? nlohmann::json(*v) : nlohmann::json();
      }
    }
  }
  for (nlohmann::json* summary : {&a, &b})
  {
    if (summary->contains("penetration"))
      (*summary)["penetration"].erase("curve");
    if (summary->contains("temporary_cavity"))
      for (const char* key : {"depth_m", "max_diameter_m", "max_time_s", "diameter_now_m"})
        (*summary)["temporary_cavity"].erase(key);
  }
  if (both_curves)
    out << "note: penetration.curve is compared as the velocity at 0, 25, 50, 75 and 100 % of "
           "the shallower run's deepest point ("
        << format_number(1e3 * deepest, 4)
        << " mm); the temporary cavity's per-slice lists are left out (plot-wound draws them)\n\n";
}

// ---------------------------------------------------------------------------------------------
// Particle files

struct PointSet
{
  std::string file;
  double time = std::nan("");
  std::vector<int> id, flag, material;
  std::vector<std::array<double, 3>> reference;
};

/// The particles_NNNNN.h5 with the largest NNNNN, if any.
std::optional<fs::path> last_particle_file(const std::string& run)
{
  std::optional<fs::path> last;
  long last_number = -1;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(run, error))
  {
    const std::string name = entry.path().filename().string();
    const std::string prefix = "particles_", suffix = ".h5";
    if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    const long number = std::stol(digits);
    if (number > last_number)
    {
      last_number = number;
      last = entry.path();
    }
  }
  if (error)
    throw CompareError("cannot list '" + run + "': " + error.message());
  return last;
}

using Handle = io::Hdf5Handle<CompareError>;

/// Silences HDF5's own error printing; our messages say what failed.
class QuietHdf5
{
public:
  QuietHdf5()
  {
    H5Eget_auto2(H5E_DEFAULT, &function, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, function, data); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

private:
  H5E_auto2_t function = nullptr;
  void* data = nullptr;
};

/// Reads dataset `name` (n rows of `n_columns`) as `type`; n is taken from the first dataset
/// read (n_rows == 0) and checked for the others.
template <typename T>
std::vector<T> read_dataset(const hid_t file, const std::string& path, const std::string& name,
                            const hid_t type, const unsigned int n_columns, std::size_t& n_rows)
{
  const std::string where = "'" + path + "', dataset '" + name + "'";
  const Handle set(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose,
                   "cannot open " + where + " (missing?)");
  const Handle space(H5Dget_space(set), H5Sclose, "cannot read the shape of " + where);
  hsize_t dims[2] = {0, 1};
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(space, dims, nullptr) < 0)
    throw CompareError(where + " has rank " + std::to_string(rank) + "; expected 1 or 2");
  if ((rank == 1 ? 1 : dims[1]) != n_columns)
    throw CompareError(where + " has " + std::to_string(rank == 1 ? 1 : dims[1]) +
                       " columns; expected " + std::to_string(n_columns));
  if (n_rows == 0)
    n_rows = dims[0];
  else if (dims[0] != n_rows)
    throw CompareError(where + " has " + std::to_string(dims[0]) + " rows; expected " +
                       std::to_string(n_rows));
  std::vector<T> values(dims[0] * n_columns);
  if (!values.empty() && H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw CompareError("cannot read " + where);
  return values;
}

PointSet read_points(const fs::path& path)
{
  const QuietHdf5 quiet;
  const std::string name = path.string();
  const Handle file(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                    "cannot open '" + name + "' as an HDF5 file");
  PointSet points;
  points.file = name;
  std::size_t n = 0;
  points.id = read_dataset<int>(file, name, "id", H5T_NATIVE_INT, 1, n);
  points.flag = read_dataset<int>(file, name, "failure", H5T_NATIVE_INT, 1, n);
  const std::vector<double> x =
      read_dataset<double>(file, name, "reference_position", H5T_NATIVE_DOUBLE, 3, n);
  points.reference.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    points.reference[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
  if (H5Lexists(file, "material_id", H5P_DEFAULT) > 0)
    points.material = read_dataset<int>(file, name, "material_id", H5T_NATIVE_INT, 1, n);
  if (H5Aexists(file, "time") > 0)
  {
    const Handle time(H5Aopen(file, "time", H5P_DEFAULT), H5Aclose,
                      "cannot open attribute 'time' of '" + name + "'");
    if (H5Aread(time, H5T_NATIVE_DOUBLE, &points.time) < 0)
      throw CompareError("cannot read attribute 'time' of '" + name + "'");
  }
  return points;
}

// ---------------------------------------------------------------------------------------------
// Matching points by reference position

using CellKey = std::array<std::int64_t, 3>;

struct CellKeyHash
{
  std::size_t operator()(const CellKey& key) const
  {
    std::size_t h = 0;
    for (const std::int64_t k : key)
      h = h * 1000003u ^ std::hash<std::int64_t>()(k);
    return h;
  }
};

CellKey cell_of(const std::array<double, 3>& x)
{
  CellKey key;
  for (unsigned int d = 0; d < 3; ++d)
    key[d] = static_cast<std::int64_t>(std::floor(x[d] / position_tolerance));
  return key;
}

/// For each point of `a`, the index of the point of `b` at the same reference position (and
/// with the same material, where both have material ids), or -1.
std::vector<long> match_points(const PointSet& a, const PointSet& b)
{
  // Buckets of b's points: head per cell, then a chain through `next`.
  std::unordered_map<CellKey, long, CellKeyHash> head;
  std::vector<long> next(b.reference.size(), -1);
  for (std::size_t j = 0; j < b.reference.size(); ++j)
  {
    auto [it, inserted] = head.try_emplace(cell_of(b.reference[j]), static_cast<long>(j));
    if (!inserted)
    {
      next[j] = it->second;
      it->second = static_cast<long>(j);
    }
  }
  const bool use_material = !a.material.empty() && !b.material.empty();
  std::vector<bool> taken(b.reference.size(), false);
  std::vector<long> match(a.reference.size(), -1);
  for (std::size_t i = 0; i < a.reference.size(); ++i)
  {
    const CellKey key = cell_of(a.reference[i]);
    for (int n = 0; n < 27 && match[i] < 0; ++n)
    {
      const CellKey neighbour{key[0] + n % 3 - 1, key[1] + (n / 3) % 3 - 1, key[2] + n / 9 - 1};
      const auto it = head.find(neighbour);
      for (long j = it == head.end() ? -1 : it->second; j >= 0 && match[i] < 0; j = next[j])
      {
        double distance = 0;
        for (unsigned int d = 0; d < 3; ++d)
          distance = std::max(distance, std::abs(a.reference[i][d] - b.reference[j][d]));
        if (!taken[j] && distance <= position_tolerance &&
            (!use_material || a.material[i] == b.material[j]))
        {
          match[i] = j;
          taken[j] = true;
        }
      }
    }
  }
  return match;
}

std::string describe(const PointSet& points)
{
  std::ostringstream text;
  text << points.file;
  if (!std::isnan(points.time))
    text << " (t = " << std::setprecision(6) << points.time << " s)";
  return text.str();
}

void compare_failure(const PointSet& a, const PointSet& b, std::ostream& out)
{
  const std::vector<long> match = match_points(a, b);
  std::array<std::array<std::size_t, 4>, 4> table{};
  std::size_t n_shared = 0, n_same_id = 0, n_same_flag = 0, n_bad_flag = 0;
  for (std::size_t i = 0; i < match.size(); ++i)
  {
    if (match[i] < 0)
      continue;
    const std::size_t j = static_cast<std::size_t>(match[i]);
    ++n_shared;
    n_same_id += a.id[i] == b.id[j] ? 1 : 0;
    const int flag_a = a.flag[i], flag_b = b.flag[j];
    if (flag_a < 0 || flag_a > 3 || flag_b < 0 || flag_b > 3)
    {
      ++n_bad_flag;
      continue;
    }
    n_same_flag += flag_a == flag_b ? 1 : 0;
    ++table[flag_a][flag_b];
  }

  out << "\nfailure flags\n  A: " << describe(a) << "\n  B: " << describe(b) << '\n';
  out << "points: A " << a.id.size() << ", B " << b.id.size() << "; shared " << n_shared
      << " (matched by reference position within " << position_tolerance << " m; same id "
      << n_same_id << "); only in A " << a.id.size() - n_shared << ", only in B "
      << b.id.size() - n_shared << '\n';
  if (n_shared == 0)
  {
    out << "no shared points: the failure fields are not compared\n";
    return;
  }
  out << "same flag: " << n_same_flag << " of " << n_shared << " (" << std::fixed
      << std::setprecision(3) << 100.0 * static_cast<double>(n_same_flag) / n_shared << " %)\n"
      << std::defaultfloat;
  if (n_bad_flag > 0)
    out << "flags outside 0..3 (not in the table): " << n_bad_flag << '\n';

  std::vector<Row> rows{{"A \\ B", flag_names[0], flag_names[1], flag_names[2], flag_names[3]}};
  for (unsigned int r = 0; r < 4; ++r)
  {
    Row row{flag_names[r], "", "", "", ""};
    for (unsigned int c = 0; c < 4; ++c)
      row[c + 1] = std::to_string(table[r][c]);
    rows.push_back(row);
  }
  out << "flags of shared points (rows A, columns B):\n";
  print_table(rows, out);
}
} // namespace

int compare_runs(const std::string& run_a, const std::string& run_b, std::ostream& out,
                 std::ostream& err)
{
  try
  {
    check_directory(run_a);
    check_directory(run_b);
    nlohmann::json summary_a = read_summary(run_a);
    nlohmann::json summary_b = read_summary(run_b);
    const std::optional<fs::path> file_a = last_particle_file(run_a),
                                  file_b = last_particle_file(run_b);
    // Read everything before printing, so an unreadable file gives only the error.
    std::optional<PointSet> points_a, points_b;
    if (file_a && file_b)
    {
      points_a = read_points(*file_a);
      points_b = read_points(*file_b);
    }

    out << "A: " << run_a << "\nB: " << run_b << "\n\n";
    align_tract_slices(summary_a, summary_b, out);
    note_face_layers(summary_a, summary_b, out);
    compact_penetration(summary_a, summary_b, out);
    compare_summaries(summary_a, summary_b, out);
    if (points_a && points_b)
      compare_failure(*points_a, *points_b, out);
    else
      out << "\nfailure flags: not compared, no particles_*.h5 in "
          << (file_a   ? run_b
              : file_b ? run_a
                       : "either run")
          << '\n';
    return 0;
  }
  catch (const CompareError& error)
  {
    err << "vulnus compare: error: " << error.what() << '\n';
    return 2;
  }
  catch (const std::exception& error)
  {
    err << "vulnus compare: error: " << error.what() << '\n';
    return 2;
  }
}
} // namespace vulnus::analysis
