// Small synthetic run directories for the analysis tests: summary.json, particles_NNNNN.h5
// (written with the HDF5 C API), history.csv and deck_used.prm, in a fresh temporary folder.
#pragma once

#include <hdf5.h>
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace vulnus::testing
{
struct SyntheticPoint
{
  int id;
  std::array<double, 3> reference; ///< m
  int flag;                        ///< 0 intact, 1 matrix, 2 fiber, 3 total
  int material = 0;                ///< 0 slab, 1 bullet
};

/// Empty folders under the system temporary directory, named after the running test;
/// removed with this object.
class Scratch
{
public:
  Scratch()
  {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    root = std::filesystem::temp_directory_path() /
           ("vulnus_analysis_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
  }
  ~Scratch()
  {
    std::error_code ignored;
    std::filesystem::remove_all(root, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  std::filesystem::path make(const std::string& name) const
  {
    std::filesystem::remove_all(root / name);
    std::filesystem::create_directories(root / name);
    return root / name;
  }

private:
  std::filesystem::path root;
};

inline void write_text(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream out(path);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

inline void write_summary(const std::filesystem::path& run, const nlohmann::json& summary)
{
  write_text(run / "summary.json", summary.dump(2) + "\n");
}

/// particles_NNNNN.h5 with the datasets of `vulnus run` the analysis reads; current positions
/// are the reference ones moved by `displacement` along +y.
inline void write_particles(const std::filesystem::path& path,
                            const std::vector<SyntheticPoint>& points, const double time,
                            const double displacement = 0.0)
{
  const std::size_t n = points.size();
  std::vector<int> id(n), flag(n), material(n);
  std::vector<double> reference(3 * n), current(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    id[i] = points[i].id;
    flag[i] = points[i].flag;
    material[i] = points[i].material;
    for (unsigned int d = 0; d < 3; ++d)
    {
      reference[3 * i + d] = points[i].reference[d];
      current[3 * i + d] = points[i].reference[d] + (d == 1 ? displacement : 0.0);
    }
  }
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0) << "cannot create " << path;
  const auto write =
      [&](const char* name, const hid_t type, const unsigned int columns, const void* data)
  {
    const hsize_t dims[2] = {n, columns};
    const hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
    const hid_t set = H5Dcreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), 0) << name;
    H5Dclose(set);
    H5Sclose(space);
  };
  write("id", H5T_NATIVE_INT, 1, id.data());
  write("failure", H5T_NATIVE_INT, 1, flag.data());
  write("material_id", H5T_NATIVE_INT, 1, material.data());
  write("reference_position", H5T_NATIVE_DOUBLE, 3, reference.data());
  write("positions", H5T_NATIVE_DOUBLE, 3, current.data());
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const hid_t attribute =
      H5Acreate2(file, "time", H5T_NATIVE_DOUBLE, scalar, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(H5Awrite(attribute, H5T_NATIVE_DOUBLE, &time), 0);
  H5Aclose(attribute);
  H5Sclose(scalar);
  H5Fclose(file);
}

/// A 10 x 10 x 10 mm block of slab points (1 mm apart, cell centres) around the y axis:
/// total failure for r < 2 mm, matrix for r < 3 mm, fiber for r < 3.5 mm, else intact;
/// plus a 2 x 2 x 2 bullet ahead of the slab.
inline std::vector<SyntheticPoint> wound_block()
{
  std::vector<SyntheticPoint> points;
  int id = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k)
      {
        const double x = (i - 4.5) * 1e-3, y = (j + 0.5) * 1e-3, z = (k - 4.5) * 1e-3;
        const double r = std::hypot(x, z);
        const int flag = r < 2e-3 ? 3 : r < 3e-3 ? 1 : r < 3.5e-3 ? 2 : 0;
        points.push_back({id++, {x, y, z}, flag, 0});
      }
  for (int n = 0; n < 8; ++n)
    points.push_back(
        {id++, {(n % 2 - 0.5) * 1e-3, -2e-3 + (n / 2 % 2) * 1e-3, (n / 4 - 0.5) * 1e-3}, 0, 1});
  return points;
}

/// A complete run directory: deck_used.prm, summary.json, history.csv, two particle files.
inline void write_wound_run(const std::filesystem::path& run)
{
  write_text(run / "deck_used.prm", "subsection Scene\n  set Bodies = slab, bullet\nend\n"
                                    "subsection Grid\n  set Cell size = 0.001 # m\nend\n");
  write_summary(
      run, {{"particles", 1008},
            {"failed", {{"matrix", 200}, {"fiber", 80}, {"total", 120}}},
            {"entrance_wound",
             {{"equivalent_diameter_m", 4e-3},
              {"aspect_ratio", 1.0},
              {"major_axis_direction", {1.0, 0.0, 0.0}}}},
            {"exit_wound",
             {{"equivalent_diameter_m", 4e-3},
              {"aspect_ratio", 1.2},
              {"major_axis_direction", {0.0, 0.0, 1.0}}}},
            {"tract", {{"depth_m", {5e-4, 1.5e-3, 2.5e-3}}, {"area_m2", {1.2e-5, 1.3e-5, 1.4e-5}}}},
            {"energy", {{"initial_J", 10.0}, {"balance_error", 1e-3}}},
            {"warnings", nlohmann::json::array()},
            {"completed", true}});
  write_text(run / "history.csv",
             "time_s,dt_s,step,kinetic_J,strain_J,failed_matrix,failed_fiber,failed_total,"
             "bullet_velocity_x,bullet_velocity_y,bullet_velocity_z\n"
             "0,0,0,10,0,0,0,0,0,150,0\n"
             "1e-5,1e-6,10,9,0.5,100,40,60,0,140,0\n"
             "2e-5,1e-6,20,8,0.8,200,80,120,0,130,0\n");
  std::vector<SyntheticPoint> before = wound_block();
  for (SyntheticPoint& point : before)
    point.flag = 0;
  write_particles(run / "particles_00000.h5", before, 0.0);
  write_particles(run / "particles_00001.h5", wound_block(), 2e-5, 1e-4);
}
} // namespace vulnus::testing
