// HDF5 + XDMF series of points or hexahedral meshes (plain HDF5 C API, atomic files).
#include "io/xdmf_series.h"

#include "io/atomic_file.h"
#include "io/hdf5_handle.h"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <istream>
#include <ostream>
#include <sstream>
#include <cstdlib>
#include <stdexcept>

namespace vulnus::io
{
namespace
{
unsigned int n_components(const Snapshot::FieldKind kind)
{
  switch (kind)
  {
  case Snapshot::FieldKind::vector:
    return 3;
  case Snapshot::FieldKind::tensor:
    return 9;
  case Snapshot::FieldKind::symmetric_tensor:
    return 6;
  default:
    return 1;
  }
}

/// An HDF5 handle whose failure reads "HDF5: cannot <what>".
class Handle : public Hdf5Handle<std::runtime_error>
{
public:
  Handle(const hid_t id, herr_t (*close)(hid_t), const std::string& what)
      : Hdf5Handle(id, close, "HDF5: cannot " + what)
  {
  }
};

void check(const herr_t status, const std::string& what)
{
  if (status < 0)
    throw std::runtime_error("HDF5: cannot " + what);
}

/// Where this process's rows go in the file's datasets.
struct RowRange
{
  std::size_t first = 0, count = 0, total = 0;
  hid_t transfer = H5P_DEFAULT; ///< collective MPI-IO transfer in parallel files
};

hid_t memory_type(const Snapshot::Element element)
{
  switch (element)
  {
  case Snapshot::Element::float32:
    return H5T_NATIVE_FLOAT;
  case Snapshot::Element::uint8:
    return H5T_NATIVE_UINT8;
  case Snapshot::Element::uint32:
    return H5T_NATIVE_UINT32;
  default:
    return H5T_NATIVE_DOUBLE;
  }
}

/// Writes rows [first, first + count) of this process's part of a dataset (count may be 0:
/// collective writes need every rank's call).
void write_rows(const hid_t set, const std::string& name, const RowRange& rows,
                const unsigned int n_columns, const hid_t type, const std::size_t first,
                const std::size_t count, const void* data)
{
  const int rank = n_columns == 1 ? 1 : 2;
  const Handle space(H5Dget_space(set), H5Sclose, "get the data space of '" + name + "'");
  const hsize_t start[2] = {static_cast<hsize_t>(rows.first + first), 0};
  const hsize_t shape[2] = {static_cast<hsize_t>(std::max<std::size_t>(count, 1)),
                            static_cast<hsize_t>(n_columns)};
  const Handle memory(H5Screate_simple(rank, shape, nullptr), H5Sclose,
                      "create a memory space for '" + name + "'");
  if (count == 0)
  {
    check(H5Sselect_none(space), "select no rows of '" + name + "'");
    check(H5Sselect_none(memory), "select no rows of '" + name + "'");
  }
  else
    check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, shape, nullptr),
          "select rows of '" + name + "'");
  check(H5Dwrite(set, type, memory, space, rows.transfer, data), "write dataset '" + name + "'");
}

/// Creates the dataset `name` and writes this process's rows: a borrowed array in one call, a
/// computed field chunk by chunk (`n_chunks` calls on every rank, for collective writes).
void write_field(const hid_t file, const Snapshot::Field& field, const RowRange& rows,
                 const std::size_t chunk_rows, const std::size_t n_chunks)
{
  const bool integer = field.kind == Snapshot::FieldKind::integer;
  const unsigned int n_columns = n_components(field.kind);
  const hid_t file_type = integer ? H5T_NATIVE_INT32 : H5T_NATIVE_DOUBLE;
  const int rank = n_columns == 1 ? 1 : 2;
  const hsize_t dims[2] = {static_cast<hsize_t>(rows.total), static_cast<hsize_t>(n_columns)};
  const Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose,
                     "create a data space for '" + field.name + "'");
  const Handle set(H5Dcreate2(file, field.name.c_str(), file_type, space, H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose, "create dataset '" + field.name + "'");
  if (rows.total == 0)
    return;
  if (field.borrowed)
  {
    write_rows(set, field.name, rows, n_columns, memory_type(field.element), 0, rows.count,
               field.borrowed);
    return;
  }
  const std::size_t width = integer ? sizeof(std::int32_t) : sizeof(double);
  std::vector<char> buffer(std::min(chunk_rows, rows.count) * n_columns * width);
  for (std::size_t c = 0; c < n_chunks; ++c)
  {
    const std::size_t first = std::min(c * chunk_rows, rows.count);
    const std::size_t count = std::min(chunk_rows, rows.count - first);
    if (count > 0)
      field.fill(first, count, buffer.data());
    write_rows(set, field.name, rows, n_columns, file_type, first, count, buffer.data());
  }
}

/// The n_cells x 8 corner indices as the int32 dataset `connectivity` (one process).
void write_hexahedra(const hid_t file, const std::vector<std::int32_t>& corners,
                     const RowRange& cells)
{
  const hsize_t dims[2] = {static_cast<hsize_t>(cells.total), 8};
  const Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose,
                     "create a data space for 'connectivity'");
  const Handle set(H5Dcreate2(file, "connectivity", H5T_NATIVE_INT32, space, H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose, "create dataset 'connectivity'");
  if (cells.total > 0)
    write_rows(set, "connectivity", cells, 8, H5T_NATIVE_INT32, 0, cells.count, corners.data());
}

std::string dimensions(const std::size_t n, const unsigned int n_columns)
{
  return n_columns == 1 ? std::to_string(n) : std::to_string(n) + " " + std::to_string(n_columns);
}

std::string data_item(const std::string& file, const std::string& dataset, const std::size_t n,
                      const unsigned int n_columns, const bool integer)
{
  std::ostringstream out;
  out << "<DataItem Dimensions=\"" << dimensions(n, n_columns) << "\" NumberType=\""
      << (integer ? "Int" : "Float") << "\" Precision=\"" << (integer ? 4 : 8)
      << "\" Format=\"HDF\">" << file << ":/" << dataset << "</DataItem>";
  return out.str();
}
} // namespace

Snapshot::Snapshot(const std::size_t n_particles) : n(n_particles) {}

void Snapshot::set_rows_per_chunk(const std::size_t rows)
{
  if (rows == 0)
    throw std::invalid_argument("particle output: rows per chunk must be positive");
  chunk_rows = rows;
}

void Snapshot::add_field(Field field)
{
  const std::string& name = field.name;
  if (name.empty() || name == "positions" || name == "connectivity" ||
      name.find_first_of("/<>&\"") != std::string::npos)
    throw std::invalid_argument("particle field name '" + name +
                                "' is empty, reserved or contains / < > & \"");
  for (const Field& existing : field_list)
    if (existing.name == name)
      throw std::invalid_argument("particle field '" + name + "' added twice");
  if (!field.borrowed && !field.fill && n > 0)
    throw std::invalid_argument("particle field '" + name + "' has no values");
  field_list.push_back(std::move(field));
}

void Snapshot::set_hexahedra(std::vector<std::int32_t> connectivity)
{
  if (connectivity.size() % 8 != 0)
    throw std::invalid_argument("hexahedra need 8 corners each; got " +
                                std::to_string(connectivity.size()) + " indices");
  for (const std::int32_t corner : connectivity)
    if (corner < 0 || static_cast<std::size_t>(corner) >= n)
      throw std::invalid_argument("a hexahedron corner " + std::to_string(corner) +
                                  " is not one of the " + std::to_string(n) + " points");
  hexahedra = std::move(connectivity);
}

void Snapshot::borrow_scalar(const std::string& name, const double* values, const Center center)
{
  add_field({name, FieldKind::scalar, values, Element::float64, {}, center});
}

void Snapshot::borrow_vector(const std::string& name, const double* values, const Center center)
{
  add_field({name, FieldKind::vector, values, Element::float64, {}, center});
}

void Snapshot::borrow_vector(const std::string& name, const float* values, const Center center)
{
  add_field({name, FieldKind::vector, values, Element::float32, {}, center});
}

void Snapshot::borrow_symmetric_tensor(const std::string& name, const double* voigt,
                                       const Center center)
{
  // The file holds XDMF's Tensor6 order XX XY XZ YY YZ ZZ (readers expand it by that order);
  // the points store xx yy zz xy yz xz.
  compute(
      name, FieldKind::symmetric_tensor,
      [voigt](const std::size_t first, const std::size_t count, void* out)
      {
        constexpr int voigt_of_xdmf[6] = {0, 3, 5, 1, 4, 2};
        auto* values = static_cast<double*>(out);
        for (std::size_t i = 0; i < count; ++i)
          for (int c = 0; c < 6; ++c)
            values[6 * i + c] = voigt[6 * (first + i) + voigt_of_xdmf[c]];
      },
      center);
}

void Snapshot::borrow_integer(const std::string& name, const std::uint8_t* values,
                              const Center center)
{
  add_field({name, FieldKind::integer, values, Element::uint8, {}, center});
}

void Snapshot::borrow_integer(const std::string& name, const std::uint32_t* values,
                              const Center center)
{
  add_field({name, FieldKind::integer, values, Element::uint32, {}, center});
}

void Snapshot::compute(const std::string& name, const FieldKind kind, Fill fill,
                       const Center center)
{
  if (!fill)
    throw std::invalid_argument("particle field '" + name + "' has no fill function");
  add_field({name, kind, nullptr, Element::float64, std::move(fill), center});
}

void write_snapshot_hdf5(const std::string& path, const double time,
                         const Snapshot& snapshot, const MPI_Comm communicator,
                         const std::size_t first_row, const std::size_t total_rows)
{
  // Report errors through exceptions, not HDF5's stack dump on stderr.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  int n_ranks = 1;
  if (communicator != MPI_COMM_NULL)
    MPI_Comm_size(communicator, &n_ranks);
  const bool parallel = n_ranks > 1;
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create file access properties");
  const Handle transfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "create transfer properties");
  if (parallel)
  {
    check(H5Pset_fapl_mpio(access, communicator, MPI_INFO_NULL), "use MPI-IO");
    check(H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE), "use collective MPI-IO");
  }
  const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access), H5Fclose,
                    "create file '" + path + "'");
  {
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar data space");
    const Handle attribute(
        H5Acreate2(file, "time", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
        "create attribute 'time' in '" + path + "'");
    check(H5Awrite(attribute, H5T_NATIVE_DOUBLE, &time), "write attribute 'time'");
  }
  const std::size_t n = snapshot.n_particles();
  const std::size_t n_cells = snapshot.n_cells();
  if (parallel && n_cells > 0)
    throw std::invalid_argument("a snapshot with hexahedra is written by one process");
  for (const Snapshot::Field& field : snapshot.fields())
    if (field.center == Snapshot::Center::cell && n_cells == 0)
      throw std::invalid_argument("field '" + field.name + "' is on cells, but the snapshot "
                                  "has no hexahedra");
  RowRange rows{parallel ? first_row : 0, n, parallel ? total_rows : n,
                parallel ? hid_t(transfer) : H5P_DEFAULT};
  const RowRange cell_rows{0, n_cells, n_cells, H5P_DEFAULT};
  unsigned long long most_rows = n;
  if (parallel)
    MPI_Allreduce(MPI_IN_PLACE, &most_rows, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, communicator);
  const std::size_t chunk_rows = snapshot.rows_per_chunk();
  const std::size_t n_chunks = (most_rows + chunk_rows - 1) / chunk_rows;
  const std::size_t n_cell_chunks = (n_cells + chunk_rows - 1) / chunk_rows;

  Snapshot::Field positions{"positions", Snapshot::FieldKind::vector,
                                    snapshot.positions(), Snapshot::Element::float64,
                                    [](std::size_t, std::size_t count, void* out)
                                    { std::fill_n(static_cast<double*>(out), 3 * count, 0.0); }};
  write_field(file, positions, rows, chunk_rows, n_chunks);
  if (n_cells > 0)
    write_hexahedra(file, snapshot.hexahedron_corners(), cell_rows);
  else
  {
    // Polyvertex connectivity 0..N-1 over all ranks: the Xdmf3 readers build no cells without it.
    Snapshot::Field connectivity{"connectivity", Snapshot::FieldKind::integer, nullptr,
                                 Snapshot::Element::float64,
                                 [&rows](std::size_t first, std::size_t count, void* out)
                                 {
                                   auto* index = static_cast<std::int32_t*>(out);
                                   for (std::size_t i = 0; i < count; ++i)
                                     index[i] = static_cast<std::int32_t>(rows.first + first + i);
                                 }};
    write_field(file, connectivity, rows, chunk_rows, n_chunks);
  }
  for (const Snapshot::Field& field : snapshot.fields())
    if (field.center == Snapshot::Center::cell)
      write_field(file, field, cell_rows, chunk_rows, n_cell_chunks);
    else
      write_field(file, field, rows, chunk_rows, n_chunks);
  check(H5Fflush(file, H5F_SCOPE_LOCAL), "flush '" + path + "'");
}

XdmfSeries::XdmfSeries(const std::string& directory, const std::string& base,
                               const MPI_Comm communicator)
    : directory(directory), base(base), comm(communicator)
{
  if (comm != MPI_COMM_NULL)
  {
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &n_ranks);
  }
}

std::string XdmfSeries::xdmf_path() const
{
  return (std::filesystem::path(directory) / (base + ".xdmf")).string();
}

std::string XdmfSeries::write(const double time, const Snapshot& snapshot)
{
  char number[16];
  std::snprintf(number, sizeof(number), "%05u", n_outputs());
  const std::string file_name = base + "_" + number + ".h5";
  const std::string path = (std::filesystem::path(directory) / file_name).string();
  std::size_t n_total = snapshot.n_particles();
  if (n_ranks == 1)
    write_file_atomically_by_name(path, [&](const std::string& tmp)
                                  { write_snapshot_hdf5(tmp, time, snapshot); });
  else
  {
    unsigned long long mine = snapshot.n_particles(), before = 0, total = 0;
    MPI_Exscan(&mine, &before, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    MPI_Allreduce(&mine, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    if (rank == 0)
      before = 0; // MPI_Exscan leaves rank 0's result undefined
    n_total = total;
    const std::string tmp = temporary_name(path);
    write_snapshot_hdf5(tmp, time, snapshot, comm, before, total);
    MPI_Barrier(comm);
    if (rank == 0)
      rename_into_place(tmp, path);
  }

  Record record{time, file_name, n_total, snapshot.n_cells(), {}};
  for (const Snapshot::Field& field : snapshot.fields())
    record.fields.push_back(FieldRecord{field.name, field.kind, field.center});
  records.push_back(record);
  write_xdmf();
  return path;
}

void XdmfSeries::save_records(std::ostream& out) const
{
  out << records.size() << '\n';
  for (const Record& record : records)
  {
    char time[40];
    std::snprintf(time, sizeof(time), "%a", record.time);
    out << time << ' ' << record.file_name.size() << ' ' << record.file_name << ' '
        << record.n_particles << ' ' << record.n_cells << ' ' << record.fields.size();
    for (const FieldRecord& field : record.fields)
      out << ' ' << static_cast<int>(field.kind) << ' ' << static_cast<int>(field.center) << ' '
          << field.name.size() << ' ' << field.name;
    out << '\n';
  }
}

void XdmfSeries::restore_records(std::istream& in)
{
  auto fail = [this]
  { throw std::runtime_error("the output list of " + base + ".xdmf in the checkpoint is malformed"); };
  auto read_name = [&](std::string& name)
  {
    std::size_t length = 0;
    if (!(in >> length) || length > 4096 || in.get() != ' ')
      fail();
    name.assign(length, '\0');
    if (!in.read(name.data(), static_cast<std::streamsize>(length)))
      fail();
  };
  std::size_t n_records = 0;
  if (!(in >> n_records) || n_records > 10000000)
    fail();
  std::vector<Record> loaded(n_records);
  for (Record& record : loaded)
  {
    std::string time;
    std::size_t n_fields = 0;
    if (!(in >> time))
      fail();
    record.time = std::strtod(time.c_str(), nullptr);
    read_name(record.file_name);
    if (!(in >> record.n_particles >> record.n_cells >> n_fields) || n_fields > 1000)
      fail();
    record.fields.resize(n_fields);
    for (FieldRecord& field : record.fields)
    {
      int kind = 0, center = 0;
      if (!(in >> kind >> center) || kind < 0 || kind > 4 || center < 0 || center > 1)
        fail();
      field.kind = static_cast<Snapshot::FieldKind>(kind);
      field.center = static_cast<Snapshot::Center>(center);
      read_name(field.name);
    }
  }
  if (in.get() != '\n')
    fail();
  records = std::move(loaded);
  write_xdmf();
}

void XdmfSeries::write_xdmf() const
{
  if (rank != 0)
    return;
  write_file_atomically(
      xdmf_path(),
      [&](std::ostream& out)
      {
        out << "<?xml version=\"1.0\" ?>\n"
            << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
            << "<Xdmf Version=\"3.0\">\n"
            << "  <Domain>\n"
            << "    <Grid Name=\"" << base
            << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
        for (const Record& record : records)
        {
          const std::size_t n = record.n_particles;
          const std::size_t n_cells = record.n_cells;
          out << std::setprecision(std::numeric_limits<double>::max_digits10);
          out << "      <Grid Name=\"" << record.file_name << "\" GridType=\"Uniform\">\n"
              << "        <Time Value=\"" << record.time << "\"/>\n";
          if (n_cells > 0)
            out << "        <Topology TopologyType=\"Hexahedron\" NumberOfElements=\"" << n_cells
                << "\">\n"
                << "          " << data_item(record.file_name, "connectivity", n_cells, 8, true)
                << "\n";
          else
            out << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
                << "\" NodesPerElement=\"1\">\n"
                << "          " << data_item(record.file_name, "connectivity", n, 1, true)
                << "\n";
          out << "        </Topology>\n"
              << "        <Geometry GeometryType=\"XYZ\">\n"
              << "          " << data_item(record.file_name, "positions", n, 3, false) << "\n"
              << "        </Geometry>\n";
          for (const FieldRecord& field : record.fields)
          {
            const char* type =
              field.kind == Snapshot::FieldKind::vector             ? "Vector"
              : field.kind == Snapshot::FieldKind::tensor           ? "Tensor"
              : field.kind == Snapshot::FieldKind::symmetric_tensor ? "Tensor6"
                                                                            : "Scalar";
            const bool on_cells = field.center == Snapshot::Center::cell;
            out << "        <Attribute Name=\"" << field.name << "\" AttributeType=\"" << type
                << "\" Center=\"" << (on_cells ? "Cell" : "Node") << "\">\n"
                << "          "
                << data_item(record.file_name, field.name, on_cells ? n_cells : n,
                             n_components(field.kind),
                             field.kind == Snapshot::FieldKind::integer)
                << "\n"
                << "        </Attribute>\n";
          }
          out << "      </Grid>\n";
        }
        out << "    </Grid>\n"
            << "  </Domain>\n"
            << "</Xdmf>\n";
      });
}
} // namespace vulnus::io
