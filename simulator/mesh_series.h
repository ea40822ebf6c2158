// The FE mesh output series (fe_mesh.xdmf + one HDF5 file per output time) of every run type
// with a far field, on the same schedule as the particles: shared vertices at their current
// positions, displacement and velocity on the vertices, stress, failure, material id and
// rank on the cells, under the particles' field names.
#pragma once

#include "io/xdmf_series.h"
#include "simulator/output_schedule.h"
#include "simulator/postprocessor.h"

#include <mpi.h>

#include <cstdint>
#include <memory>

namespace vulnus::simulator
{
class MeshSeries : public Postprocessor
{
public:
  /// `material_id`: the body index the far field's tissue has among the particles' bodies.
  /// Collective over `communicator`; rank 0 writes the files.
  MeshSeries(const std::string& directory, double interval,
             std::int32_t material_id, MPI_Comm communicator);

  void start(Stepper& stepper) override;
  void resume(Stepper& stepper, const io::RunProgress& progress) override;
  void after_step(Stepper& stepper) override;
  void finish(Stepper& stepper) override;
  void save_progress(io::RunProgress& progress) const override;
  std::string last_state() const override;

private:
  void write(Stepper& stepper);

  std::string directory;
  MPI_Comm communicator;
  std::unique_ptr<io::XdmfSeries> output; ///< on rank 0 alone (the mesh is gathered there)
  OutputSchedule schedule;
  std::int32_t material_id;
  double last_time = -1.0; ///< s, of the newest mesh output (every rank)
};
} // namespace vulnus::simulator
