// Particle output as HDF5 + XDMF for ParaView: one HDF5 file per output time
// (`particles_NNNNN.h5`: positions and named fields) written atomically, and one XDMF time
// series (`particles.xdmf`, Polyvertex topology, Temporal collection) rewritten atomically
// after each output so that ParaView can open it at any moment. Plain HDF5 C API.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace vulnus::app
{
/// The particle set at one output time: positions and named per-particle fields, copied in.
class ParticleSnapshot
{
public:
  enum class FieldKind
  {
    scalar, ///< n values, double
    vector, ///< n x 3, double
    tensor, ///< n x 9, double, row-major (add_symmetric_tensor stores expanded)
    integer, ///< n values, int32 (failure flag, material id)
    symmetric_tensor ///< n x 6, double, Voigt order xx yy zz xy yz xz (XDMF Tensor6)
  };

  struct Field
  {
    std::string name;
    FieldKind kind;
    std::vector<double> values;         ///< scalar, vector, tensor (copied in)
    std::vector<std::int32_t> integers; ///< integer
    const double* borrowed = nullptr;   ///< instead of values, for borrow_* fields
    const double* data() const { return borrowed ? borrowed : values.data(); }
  };

  explicit ParticleSnapshot(std::size_t n_particles);

  std::size_t n_particles() const { return n; }

  /// n x 3 coordinates, interleaved x y z (an array of Eigen::Vector3d can be passed as
  /// `positions[0].data()`).
  void set_positions(const double* xyz);
  /// The borrow_* calls keep a pointer instead of a copy (no memory per point for output):
  /// the array must stay unchanged until the snapshot is written.
  void borrow_positions(const double* xyz) { borrowed_positions = xyz; }
  void borrow_vector(const std::string& name, const double* values);
  /// n x 6 in Voigt order xx yy zz xy yz xz, stored as 6 components (XDMF Tensor6).
  void borrow_symmetric_tensor(const std::string& name, const double* voigt);
  void add_scalar(const std::string& name, const double* values);
  /// n x 3, interleaved.
  void add_vector(const std::string& name, const double* values);
  /// n x 6 in Voigt order xx yy zz xy yz xz; stored as a full 3 x 3 tensor.
  void add_symmetric_tensor(const std::string& name, const double* voigt);
  /// n x 9 row-major (an array of symmetric Eigen::Matrix3d can be passed directly).
  void add_tensor(const std::string& name, const double* values);
  void add_integer(const std::string& name, const std::int32_t* values);

  /// Integer field from any integer type (e.g. std::uint8_t failure flags).
  template <class Integer> void add_integer_from(const std::string& name, const Integer* values)
  {
    std::vector<std::int32_t> converted(n);
    for (std::size_t i = 0; i < n; ++i)
      converted[i] = static_cast<std::int32_t>(values[i]);
    add_integer(name, converted.data());
  }

  /// n x 3, interleaved; null until set (written as zeros).
  const double* positions() const
  {
    if (borrowed_positions)
      return borrowed_positions;
    return position_values.empty() ? nullptr : position_values.data();
  }
  const std::vector<Field>& fields() const { return field_list; }

private:
  Field& new_field(const std::string& name, FieldKind kind);

  std::size_t n;
  std::vector<double> position_values;
  const double* borrowed_positions = nullptr;
  std::vector<Field> field_list;
};

class ParticleOutput
{
public:
  /// Outputs go to `directory` (must exist) as `<base>_NNNNN.h5` and `<base>.xdmf`. With a
  /// communicator of several ranks, write() is collective: each rank passes its own points
  /// and all of them land in one file (parallel HDF5); rank 0 writes the XDMF series.
  explicit ParticleOutput(const std::string& directory, const std::string& base = "particles",
                          MPI_Comm communicator = MPI_COMM_NULL);

  /// Write the snapshot at `time` (s): the HDF5 file, then the XDMF series. Returns the path
  /// of the HDF5 file. Throws std::runtime_error if a file cannot be written.
  std::string write(double time, const ParticleSnapshot& snapshot);

  unsigned int n_outputs() const { return static_cast<unsigned int>(records.size()); }

  /// The list of outputs written so far (times, files, fields), for a checkpoint; restore
  /// continues the series after them (files written later by the interrupted run are
  /// overwritten). restore throws std::runtime_error on malformed input.
  void save_records(std::ostream& out) const;
  void restore_records(std::istream& in);
  std::string xdmf_path() const;
  /// Simulated time of the newest output (0 before the first).
  double last_time() const { return records.empty() ? 0.0 : records.back().time; }

private:
  struct FieldRecord
  {
    std::string name;
    ParticleSnapshot::FieldKind kind;
  };
  struct Record
  {
    double time;
    std::string file_name; ///< relative to the directory
    std::size_t n_particles;
    std::vector<FieldRecord> fields;
  };

  void write_xdmf() const;

  std::string directory;
  std::string base;
  MPI_Comm comm;
  int rank = 0;
  int n_ranks = 1;
  std::vector<Record> records;
};

/// Write one snapshot as an HDF5 file at `path` (not atomic by itself): datasets
/// `/positions` (n x 3), one dataset per field named after it, and the attribute `time` on
/// the root group. With a communicator of several ranks (collective): every rank's snapshot
/// goes to rows [first_row, first_row + its size) of datasets of `total_rows` rows.
void write_particle_hdf5(const std::string& path, double time, const ParticleSnapshot& snapshot,
                         MPI_Comm communicator = MPI_COMM_NULL, std::size_t first_row = 0,
                         std::size_t total_rows = 0);
} // namespace vulnus::app
