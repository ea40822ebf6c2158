// Particle output as HDF5 + XDMF for ParaView: one HDF5 file per output time
// (`particles_NNNNN.h5`: positions and named fields) written atomically, and one XDMF time
// series (`particles.xdmf`, Polyvertex topology, Temporal collection) rewritten atomically
// after each output so that ParaView can open it at any moment. Plain HDF5 C API.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace vulnus::io
{
/// The particle set at one output time: positions and named per-particle fields. Fields are
/// borrowed (a pointer to the caller's array, which must stay unchanged until the snapshot is
/// written) or computed in chunks of rows while writing, so output costs no memory per point.
class ParticleSnapshot
{
public:
  enum class FieldKind
  {
    scalar, ///< n values, double
    vector, ///< n x 3, double
    tensor, ///< n x 9, double, row-major
    integer, ///< n values, int32 (failure flag, material id)
    symmetric_tensor ///< n x 6, double, Voigt order xx yy zz xy yz xz (XDMF Tensor6)
  };
  /// Element type of a borrowed array; the file holds doubles (int32 for integer fields) and
  /// HDF5 converts while writing.
  enum class Element
  {
    float64,
    float32,
    uint8,
    uint32
  };
  /// Fills rows [first, first + count) of a computed field: count x components values,
  /// interleaved, as double (int32 for integer fields).
  using Fill = std::function<void(std::size_t first, std::size_t count, void* out)>;

  struct Field
  {
    std::string name;
    FieldKind kind;
    const void* borrowed = nullptr; ///< the whole array, or null for a computed field
    Element element = Element::float64;
    Fill fill;
  };

  explicit ParticleSnapshot(std::size_t n_particles);

  std::size_t n_particles() const { return n; }

  /// n x 3 coordinates, interleaved x y z (an array of Eigen::Vector3d can be passed as
  /// `positions[0].data()`); written as zeros when never set.
  void borrow_positions(const double* xyz) { borrowed_positions = xyz; }
  void borrow_scalar(const std::string& name, const double* values);
  /// n x 3, interleaved.
  void borrow_vector(const std::string& name, const double* values);
  void borrow_vector(const std::string& name, const float* values);
  /// n x 6 in Voigt order xx yy zz xy yz xz, stored as 6 components (XDMF Tensor6).
  void borrow_symmetric_tensor(const std::string& name, const double* voigt);
  void borrow_integer(const std::string& name, const std::uint8_t* values);
  void borrow_integer(const std::string& name, const std::uint32_t* values);
  /// A field produced chunk by chunk while writing (values derived from several arrays).
  void compute(const std::string& name, FieldKind kind, Fill fill);

  /// Rows computed at a time (memory of a computed field while writing: rows x components).
  void set_rows_per_chunk(std::size_t rows);
  std::size_t rows_per_chunk() const { return chunk_rows; }

  /// n x 3, interleaved; null until set.
  const double* positions() const { return borrowed_positions; }
  const std::vector<Field>& fields() const { return field_list; }

private:
  void add_field(Field field);

  std::size_t n;
  std::size_t chunk_rows = 65536;
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
  /// True when the newest output was written at `time` (a final output would repeat it, and
  /// ParaView shows an empty frame for two grids at one time).
  bool has_output_at(const double time) const
  {
    return !records.empty() && records.back().time == time;
  }

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
} // namespace vulnus::io
