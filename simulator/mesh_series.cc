// FE mesh outputs on the schedule; their records travel with the checkpoints.
#include "simulator/mesh_series.h"

#include "fem/far_field_solver.h"
#include "io/disk_space.h"

#include <mpi.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace vulnus::simulator
{
namespace
{
bool is_root(const MPI_Comm communicator)
{
  int rank = 0;
  MPI_Comm_rank(communicator, &rank);
  return rank == 0;
}

/// Rank 0's error message (empty for none) on every rank.
std::string broadcast_error(std::string message, const MPI_Comm communicator)
{
  unsigned long length = message.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG, 0, communicator);
  message.resize(length);
  MPI_Bcast(message.data(), static_cast<int>(length), MPI_CHAR, 0, communicator);
  return message;
}
} // namespace

MeshSeries::MeshSeries(const std::string& directory, const double interval,
                       const std::int32_t material_id, const MPI_Comm communicator)
    : directory(directory), communicator(communicator), schedule(interval),
      material_id(material_id)
{
  if (is_root(communicator))
    output = std::make_unique<io::XdmfSeries>(directory, "fe_mesh");
}

void MeshSeries::write(Stepper& stepper)
{
  // A far field the adaptive zone has taken in whole has no mesh left to write.
  if (stepper.fe_side()->n_active_cells() == 0)
  {
    last_time = stepper.time();
    return;
  }
  const fem::FeMeshForOutput mesh = stepper.fe_side()->mesh_for_output(); // collective
  std::string error;
  if (output) try
  {
    using Center = io::Snapshot::Center;
    const std::size_t n_vertices = mesh.positions.size() / 3, n_cells = mesh.failure.size();
    // About 100 bytes a vertex and 120 a cell (positions, fields, connectivity).
    std::ostringstream what;
    what << "the FE mesh output at t = " << stepper.time() << " s";
    io::require_free_space(directory, 100.0 * n_vertices + 120.0 * n_cells, what.str());
    io::Snapshot snapshot(n_vertices);
    snapshot.set_hexahedra(mesh.hexahedra);
    snapshot.borrow_positions(mesh.positions.data());
    snapshot.borrow_vector("displacement", mesh.displacement.data());
    snapshot.borrow_vector("velocity", mesh.velocity.data());
    snapshot.borrow_symmetric_tensor("stress", mesh.stress.data(), Center::cell);
    snapshot.borrow_integer("failure", mesh.failure.data(), Center::cell);
    const std::int32_t id = material_id;
    snapshot.compute(
        "material_id", io::Snapshot::FieldKind::integer,
        [id](std::size_t, std::size_t count, void* out)
        { std::fill_n(static_cast<std::int32_t*>(out), count, id); },
        Center::cell);
    snapshot.borrow_integer("rank", mesh.rank.data(), Center::cell);
    output->write(stepper.time(), snapshot);
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  // Every rank learns of a failed write, so that all of them end the run together.
  error = broadcast_error(error, communicator);
  if (!error.empty())
    throw std::runtime_error(error);
  last_time = stepper.time();
}

void MeshSeries::start(Stepper& stepper) { write(stepper); }

void MeshSeries::resume(Stepper& stepper, const io::RunProgress& progress)
{
  if (output)
  {
    std::istringstream records(progress.mesh_output_records);
    output->restore_records(records);
    last_time = output->last_time();
  }
  MPI_Bcast(&last_time, 1, MPI_DOUBLE, 0, communicator);
  schedule.resume(progress.next_output, stepper.time());
}

void MeshSeries::save_progress(io::RunProgress& progress) const
{
  progress.next_output = schedule.next_time(); // the particles' schedule too, when both exist
  if (output)
  {
    std::ostringstream records;
    output->save_records(records);
    progress.mesh_output_records = records.str();
  }
}

void MeshSeries::after_step(Stepper& stepper)
{
  if (schedule.due(stepper.time()))
  {
    write(stepper);
    schedule.advance();
  }
}

void MeshSeries::finish(Stepper& stepper)
{
  if (stepper.time() != last_time) // a final output would repeat the last one: an empty frame
    write(stepper);
}

std::string MeshSeries::last_state() const
{
  std::ostringstream o;
  o << "the last FE mesh output (t = " << last_time << " s) in " << directory << "/fe_mesh.xdmf";
  return o.str();
}
} // namespace vulnus::simulator
