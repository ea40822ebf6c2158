// The particle output series (particles.xdmf + one HDF5 file per output time) of every run
// type with an MPM side: the initial state, every output interval, and the final state
// unless an output was just written at that time.
#pragma once

#include "io/xdmf_series.h"
#include "simulator/output_schedule.h"
#include "simulator/postprocessor.h"

#include <mpi.h>

namespace vulnus::simulator
{
class ParticleSeries : public Postprocessor
{
public:
  /// Collective over `communicator`: all ranks write their points into one file per time.
  ParticleSeries(const std::string& directory, double interval,
                 MPI_Comm communicator);

  void start(Stepper& stepper) override;
  void resume(Stepper& stepper, const io::RunProgress& progress) override;
  void after_step(Stepper& stepper) override;
  void finish(Stepper& stepper) override;
  void save_progress(io::RunProgress& progress) const override;
  std::string last_state() const override;

private:
  void write(const Stepper& stepper);

  std::string directory;
  io::XdmfSeries output;
  OutputSchedule schedule;
};
} // namespace vulnus::simulator
