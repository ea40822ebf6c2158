// Output writers: HDF5 + XDMF particle output read back through the HDF5 API, CSV history,
// atomic files (no .tmp left behind, no partial file on failure), summary.json.
#include "io/atomic_file.h"
#include "io/csv_history.h"
#include "io/disk_space.h"
#include "io/xdmf_series.h"
#include "io/summary_json.h"

#include "command_runner.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <array>
#include <cstdint>
#include <vector>

namespace
{
using namespace vulnus::io;
using namespace vulnus::testing;
namespace fs = std::filesystem;

std::vector<double> read_doubles(const hid_t file, const std::string& name,
                                 std::vector<hsize_t>& dims)
{
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << name;
  const hid_t space = H5Dget_space(set);
  dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hsize_t n = 1;
  for (const hsize_t d : dims)
    n *= d;
  std::vector<double> values(n);
  EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Sclose(space);
  H5Dclose(set);
  return values;
}

void expect_no_temporaries(const fs::path& directory)
{
  for (const auto& entry : fs::directory_iterator(directory))
    EXPECT_NE(entry.path().extension(), ".tmp") << entry.path();
}

// Borrowed arrays are written as they are when write() runs; a symmetric tensor borrowed in
// Voigt order (xx yy zz xy yz xz) is stored in XDMF's Tensor6 order (XX XY XZ YY YZ ZZ), the
// order ParaView's readers expand it by; the points get a Polyvertex connectivity 0..N-1.
TEST(XdmfSeries, BorrowedArraysAndTensor6)
{
  ScratchDirectory scratch("particles_borrowed");
  const std::vector<double> x = {0, 0, 0, 1, 2, 3};
  std::vector<double> v = {1, 0, 0, 0, 1, 0};
  const std::vector<double> voigt = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  Snapshot snapshot(2);
  snapshot.borrow_positions(x.data());
  snapshot.borrow_vector("velocity", v.data());
  snapshot.borrow_symmetric_tensor("stress", voigt.data());
  v[4] = 42.0; // borrowed, not copied
  XdmfSeries output(scratch.path.string());
  const std::string path = output.write(1e-6, snapshot);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::vector<hsize_t> dims;
  EXPECT_EQ(read_doubles(file, "positions", dims), x);
  EXPECT_EQ(read_doubles(file, "velocity", dims)[4], 42.0);
  EXPECT_EQ(read_doubles(file, "stress", dims),
            (std::vector<double>{1, 4, 6, 2, 5, 3, 7, 10, 12, 8, 11, 9}));
  EXPECT_EQ(dims, (std::vector<hsize_t>{2, 6}));
  EXPECT_EQ(read_doubles(file, "connectivity", dims), (std::vector<double>{0, 1}));
  H5Fclose(file);
  const std::string xdmf = read_text(output.xdmf_path());
  EXPECT_NE(xdmf.find("NodesPerElement=\"1\">\n          <DataItem Dimensions=\"2\" NumberType=\"Int\""),
            std::string::npos)
      << xdmf;
  EXPECT_NE(xdmf.find("Name=\"stress\" AttributeType=\"Tensor6\""), std::string::npos) << xdmf;
  EXPECT_NE(xdmf.find("Dimensions=\"2 6\""), std::string::npos) << xdmf;
}

// Computed fields are written in chunks of rows: 20 rows in chunks of 7 (7, 7, 6) land in
// the right rows; float and unsigned arrays are converted to the file's double and int32.
TEST(XdmfSeries, ComputedFieldsInChunksAndConvertedArrays)
{
  ScratchDirectory scratch("particles_chunks");
  const std::size_t n = 20;
  std::vector<float> reference(3 * n);
  std::vector<std::uint32_t> ids(n);
  std::vector<double> expected_reference(3 * n), expected_ids(n), expected_half(n), expected_thrice(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      reference[3 * i + d] = 0.25f * static_cast<float>(i) + static_cast<float>(d);
      expected_reference[3 * i + d] = reference[3 * i + d];
    }
    ids[i] = static_cast<std::uint32_t>(1000 + i);
    expected_ids[i] = 1000.0 + static_cast<double>(i);
    expected_half[i] = 0.5 * static_cast<double>(i);
    expected_thrice[i] = 3.0 * static_cast<double>(i);
  }
  Snapshot snapshot(n);
  snapshot.set_rows_per_chunk(7);
  snapshot.borrow_vector("reference_position", reference.data());
  snapshot.borrow_integer("id", ids.data());
  std::vector<std::size_t> calls;
  snapshot.compute("half", Snapshot::FieldKind::scalar,
                   [&calls](std::size_t first, std::size_t count, void* out)
                   {
                     calls.push_back(count);
                     for (std::size_t i = 0; i < count; ++i)
                       static_cast<double*>(out)[i] = 0.5 * static_cast<double>(first + i);
                   });
  snapshot.compute("thrice", Snapshot::FieldKind::integer,
                   [](std::size_t first, std::size_t count, void* out)
                   {
                     for (std::size_t i = 0; i < count; ++i)
                       static_cast<std::int32_t*>(out)[i] = static_cast<std::int32_t>(3 * (first + i));
                   });
  XdmfSeries output(scratch.path.string());
  const std::string path = output.write(0.0, snapshot);
  EXPECT_EQ(calls, (std::vector<std::size_t>{7, 7, 6}));
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::vector<hsize_t> dims;
  EXPECT_EQ(read_doubles(file, "positions", dims), std::vector<double>(3 * n, 0.0));
  EXPECT_EQ(read_doubles(file, "reference_position", dims), expected_reference);
  EXPECT_EQ(read_doubles(file, "id", dims), expected_ids);
  EXPECT_EQ(read_doubles(file, "half", dims), expected_half);
  EXPECT_EQ(read_doubles(file, "thrice", dims), expected_thrice);
  H5Fclose(file);
  EXPECT_THROW(snapshot.set_rows_per_chunk(0), std::invalid_argument);
}

TEST(XdmfSeries, RoundTripThroughHdf5AndXdmfNamesDatasets)
{
  ScratchDirectory scratch("particles");
  const std::size_t n = 3;
  const std::vector<double> x = {0, 0, 0, 1, 2, 3, -1, 0.5, 4};
  const std::vector<double> v = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::vector<double> mass = {0.1, 0.2, 0.3};
  const std::vector<double> stress = {1, 2, 3, 4, 5, 6, 0, 0, 0, 0, 0, 0, 7, 8, 9, 10, 11, 12};
  const std::vector<std::uint8_t> failure = {0, 1, 3};

  Snapshot snapshot(n);
  snapshot.borrow_positions(x.data());
  snapshot.borrow_vector("velocity", v.data());
  snapshot.borrow_scalar("mass", mass.data());
  // Voigt xx yy zz xy yz xz expanded to a row-major full tensor while writing.
  snapshot.compute("stress", Snapshot::FieldKind::tensor,
                   [&stress](std::size_t first, std::size_t count, void* out)
                   {
                     static const unsigned int voigt_of[9] = {0, 3, 5, 3, 1, 4, 5, 4, 2};
                     auto* full = static_cast<double*>(out);
                     for (std::size_t i = 0; i < count; ++i)
                       for (unsigned int c = 0; c < 9; ++c)
                         full[9 * i + c] = stress[6 * (first + i) + voigt_of[c]];
                   });
  snapshot.borrow_integer("failure", failure.data());
  EXPECT_THROW(snapshot.borrow_scalar("mass", mass.data()), std::invalid_argument);
  EXPECT_THROW(snapshot.compute("empty", Snapshot::FieldKind::scalar, {}),
               std::invalid_argument);

  XdmfSeries output(scratch.path.string());
  const std::string first = output.write(0.0, snapshot);
  const std::string second = output.write(2.5e-6, snapshot);
  EXPECT_EQ(fs::path(first).filename(), "particles_00000.h5");
  EXPECT_EQ(fs::path(second).filename(), "particles_00001.h5");
  expect_no_temporaries(scratch.path);

  const hid_t file = H5Fopen(second.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::vector<hsize_t> dims;
  EXPECT_EQ(read_doubles(file, "positions", dims), x);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(read_doubles(file, "velocity", dims), v);
  EXPECT_EQ(read_doubles(file, "mass", dims), mass);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3}));
  const std::vector<double> full = read_doubles(file, "stress", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 9}));
  // Particle 0: xx yy zz xy yz xz = 1..6 -> row-major full tensor.
  EXPECT_EQ(std::vector<double>(full.begin(), full.begin() + 9),
            (std::vector<double>{1, 4, 6, 4, 2, 5, 6, 5, 3}));
  EXPECT_EQ(full[9 * 2 + 0], 7.0);
  EXPECT_EQ(full[9 * 2 + 1], 10.0);

  std::array<std::int32_t, 3> flags{};
  const hid_t set = H5Dopen2(file, "failure", H5P_DEFAULT);
  ASSERT_GE(set, 0);
  EXPECT_GE(H5Dread(set, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, flags.data()), 0);
  EXPECT_EQ(flags, (std::array<std::int32_t, 3>{0, 1, 3}));
  H5Dclose(set);
  double time = -1;
  const hid_t attribute = H5Aopen(file, "time", H5P_DEFAULT);
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &time);
  H5Aclose(attribute);
  EXPECT_EQ(time, 2.5e-6);
  H5Fclose(file);

  const std::string xdmf = read_text(output.xdmf_path());
  EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(xdmf.find("TopologyType=\"Polyvertex\" NumberOfElements=\"3\""), std::string::npos);
  EXPECT_NE(xdmf.find("<Time Value=\"2.5000000000000002e-06\"/>"), std::string::npos) << xdmf;
  for (const char* item : {"particles_00000.h5:/positions", "particles_00001.h5:/positions",
                           "particles_00001.h5:/velocity", "particles_00001.h5:/mass",
                           "particles_00001.h5:/stress", "particles_00001.h5:/failure"})
    EXPECT_NE(xdmf.find(item), std::string::npos) << item;
  EXPECT_NE(xdmf.find("Name=\"stress\" AttributeType=\"Tensor\""), std::string::npos);
  EXPECT_NE(xdmf.find("Name=\"velocity\" AttributeType=\"Vector\""), std::string::npos);
  EXPECT_NE(xdmf.find("Dimensions=\"3 9\""), std::string::npos);
  EXPECT_NE(xdmf.find("NumberType=\"Int\" Precision=\"4\""), std::string::npos);
}

TEST(AtomicFile, FailedWriterLeavesNeitherFileNorTemporary)
{
  ScratchDirectory scratch("atomic");
  const std::string path = (scratch.path / "a.txt").string();
  write_file_atomically(path, [](std::ostream& out) { out << "first\n"; });
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out)
                                     {
                                       out << "partial";
                                       throw std::runtime_error("crash");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_text(path), "first\n");
  expect_no_temporaries(scratch.path);
  EXPECT_THROW(
      write_file_atomically((scratch.path / "no/such/dir/b.txt").string(), [](std::ostream&) {}),
      std::runtime_error);
}

// The free-space check against the real file system: a need beyond any disk is refused with
// the place and both sizes named; a small one passes.
TEST(DiskSpace, AnOutputLargerThanTheFreeSpaceIsRefusedBeforeWriting)
{
  ScratchDirectory scratch("disk_space");
  EXPECT_NO_THROW(require_free_space(scratch.path.string(), 1.0, "a tiny file"));
  try
  {
    require_free_space(scratch.path.string(), 1e21, "the particle output at t = 0.001 s");
    FAIL() << "a zettabyte fitted";
  }
  catch (const std::runtime_error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("not enough disk space for the particle output at t = 0.001 s"),
              std::string::npos) << message;
    EXPECT_NE(message.find(scratch.path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("1000000000000.00 GB needed"), std::string::npos) << message;
    EXPECT_NE(message.find("Output/Particle output interval"), std::string::npos) << message;
  }
}

TEST(CsvHistory, HeaderAndWholeRows)
{
  ScratchDirectory scratch("csv");
  const std::string path = (scratch.path / "history.csv").string();
  {
    CsvHistory history(path, {"time", "dt", "kinetic_energy"}, 2);
    history.add_row({0.0, 1e-7, 5.0});
    EXPECT_EQ(read_text(path), "time,dt,kinetic_energy\n"); // buffered
    history.add_row({1e-7, 1e-7, 4.5});
    EXPECT_EQ(read_text(path), "time,dt,kinetic_energy\n0,1e-07,5\n1e-07,1e-07,4.5\n");
    history.add_row({2e-7, 1e-7, 4.25});
    EXPECT_THROW(history.add_row({1.0}), std::invalid_argument);
    EXPECT_EQ(history.n_rows(), 3u);
  }
  EXPECT_EQ(read_text(path),
            "time,dt,kinetic_energy\n0,1e-07,5\n1e-07,1e-07,4.5\n2e-07,1e-07,4.25\n");
  EXPECT_THROW(CsvHistory(path, {"a,b"}), std::invalid_argument);
}

TEST(SummaryJson, WrittenAtomically)
{
  ScratchDirectory scratch("summary");
  const std::string path = (scratch.path / "summary.json").string();
  write_summary_json(path, {{"bullet", {{"exit_velocity", 120.5}}}, {"steps", 10}});
  const nlohmann::json read = nlohmann::json::parse(read_text(path));
  EXPECT_EQ(read["bullet"]["exit_velocity"], 120.5);
  EXPECT_EQ(read["steps"], 10);
  expect_no_temporaries(scratch.path);
}
} // namespace
