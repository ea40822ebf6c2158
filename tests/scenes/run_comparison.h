// What two runs of one scene must share to count as the same run: the summary without its
// wall-clock figures, and every dataset of their HDF5 outputs (the files themselves differ:
// HDF5 stores the datasets' creation times).
#pragma once

#include "../app/command_runner.h"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace vulnus::testing
{
/// summary.json without the entries that measure this process's performance: wall-clock
/// times and the MPI traffic (a restarted run counts its own from the restart).
inline nlohmann::json summary_without_timing(const std::filesystem::path& run)
{
  nlohmann::json s = nlohmann::json::parse(read_text(run / "summary.json"));
  s.erase("wall_seconds");
  s.erase("particle_steps_per_second");
  if (s.contains("hybrid"))
    for (const char* key : {"mpm_seconds", "coupling_and_fe_seconds", "fe_phase_seconds"})
      s["hybrid"].erase(key);
  if (s.contains("hybrid") && s["hybrid"].contains("balance"))
    s["hybrid"]["balance"].erase("effective_mass_seconds");
  if (s.contains("hybrid") && s["hybrid"].contains("adaptive_zone"))
    for (const char* key : {"check_seconds", "conversion_seconds"})
      s["hybrid"]["adaptive_zone"].erase(key);
  if (s.contains("mpi"))
    s["mpi"].erase("bytes_sent");
  return s;
}

/// Dataset `name` of an HDF5 file as doubles (a failed expectation, and no values, when the
/// file or the dataset is missing).
inline std::vector<double> dataset(const std::filesystem::path& file, const std::string& name)
{
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  if (f < 0)
    return {};
  const hid_t set = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << file << " has no dataset " << name;
  if (set < 0)
  {
    H5Fclose(f);
    return {};
  }
  const hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<double> values(static_cast<std::size_t>(std::max<hssize_t>(n, 0)));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(f);
  return values;
}

/// Names of the datasets in the root group of an HDF5 file.
inline std::vector<std::string> dataset_names(const std::filesystem::path& file)
{
  std::vector<std::string> names;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  if (f < 0)
    return names;
  H5Literate(f, H5_INDEX_NAME, H5_ITER_INC, nullptr,
              [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t
              {
                static_cast<std::vector<std::string>*>(out)->push_back(name);
                return 0;
              },
              &names);
  H5Fclose(f);
  return names;
}

/// Every dataset of two HDF5 files equal, value for value.
inline void expect_same_datasets(const std::filesystem::path& expected,
                                 const std::filesystem::path& actual)
{
  const std::vector<std::string> names = dataset_names(expected);
  EXPECT_FALSE(names.empty()) << expected;
  EXPECT_EQ(names, dataset_names(actual)) << actual;
  for (const std::string& name : names)
    EXPECT_EQ(dataset(expected, name), dataset(actual, name)) << actual << ": " << name;
}
} // namespace vulnus::testing
