// HDF5 + XDMF time series for ParaView, of points (the particles: Polyvertex topology) or
// of a hexahedral mesh (the far field: shared nodes, Hexahedron topology, fields on nodes or
// cells): one HDF5 file per output time (`<base>_NNNNN.h5`: positions, connectivity and
// named fields) written atomically, and one XDMF 3 series (`<base>.xdmf`, Temporal
// collection, times at full precision) rewritten atomically after each output so that
// ParaView can open it at any moment. Plain HDF5 C API.
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
/// The points (particles or mesh nodes) at one output time: positions, optionally the
/// hexahedra joining them, and named fields on the points or on the hexahedra. Fields are
/// borrowed (a pointer to the caller's array, which must stay unchanged until the snapshot is
/// written) or computed in chunks of rows while writing, so output costs no memory per point.
class Snapshot
{
public:
  /// Where a field lives: one row per point, or one per hexahedron.
  enum class Center
  {
    node,
    cell
  };
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
    Center center = Center::node;
  };

  explicit Snapshot(std::size_t n_particles);

  std::size_t n_particles() const { return n; }

  /// n x 3 coordinates, interleaved x y z (an array of Eigen::Vector3d can be passed as
  /// `positions[0].data()`); written as zeros when never set.
  void borrow_positions(const double* xyz) { borrowed_positions = xyz; }
  /// Joins the points into hexahedra: n_cells x 8 point indices, in XDMF's (and VTK's)
  /// order: the bottom face counter-clockwise seen from above, then the top face. Without
  /// hexahedra the points are written as a Polyvertex. A snapshot with hexahedra is written
  /// by one process.
  void set_hexahedra(std::vector<std::int32_t> connectivity);
  std::size_t n_cells() const { return hexahedra.size() / 8; }
  const std::vector<std::int32_t>& hexahedron_corners() const { return hexahedra; }

  /// Fields with Center::cell have one row per hexahedron, the others one per point.
  void borrow_scalar(const std::string& name, const double* values, Center center = Center::node);
  /// n x 3, interleaved.
  void borrow_vector(const std::string& name, const double* values, Center center = Center::node);
  void borrow_vector(const std::string& name, const float* values, Center center = Center::node);
  /// n x 6 in Voigt order xx yy zz xy yz xz, stored as 6 components (XDMF Tensor6).
  void borrow_symmetric_tensor(const std::string& name, const double* voigt,
                               Center center = Center::node);
  void borrow_integer(const std::string& name, const std::uint8_t* values,
                      Center center = Center::node);
  void borrow_integer(const std::string& name, const std::uint32_t* values,
                      Center center = Center::node);
  /// A field produced chunk by chunk while writing (values derived from several arrays).
  void compute(const std::string& name, FieldKind kind, Fill fill, Center center = Center::node);

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
  std::vector<std::int32_t> hexahedra;
  std::vector<Field> field_list;
};

class XdmfSeries
{
public:
  /// Outputs go to `directory` (must exist) as `<base>_NNNNN.h5` and `<base>.xdmf`. With a
  /// communicator of several ranks, write() is collective: each rank passes its own points
  /// and all of them land in one file (parallel HDF5); rank 0 writes the XDMF series.
  explicit XdmfSeries(const std::string& directory, const std::string& base = "particles",
                          MPI_Comm communicator = MPI_COMM_NULL);

  /// Write the snapshot at `time` (s): the HDF5 file, then the XDMF series. Returns the path
  /// of the HDF5 file. Throws std::runtime_error if a file cannot be written.
  std::string write(double time, const Snapshot& snapshot);

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
    Snapshot::FieldKind kind;
    Snapshot::Center center;
  };
  struct Record
  {
    double time;
    std::string file_name; ///< relative to the directory
    std::size_t n_particles;
    std::size_t n_cells; ///< hexahedra; 0 for a Polyvertex of the points
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
void write_snapshot_hdf5(const std::string& path, double time, const Snapshot& snapshot,
                         MPI_Comm communicator = MPI_COMM_NULL, std::size_t first_row = 0,
                         std::size_t total_rows = 0);
} // namespace vulnus::io
