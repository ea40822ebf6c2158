// The FE mesh output series (fe_mesh.xdmf + one HDF5 file per output time) of every run type
// with a far field, on the same schedule as the particles.
#pragma once

#include "simulator/output_schedule.h"
#include "simulator/postprocessor.h"

namespace vulnus::simulator
{
class MeshSeries : public Postprocessor
{
public:
  MeshSeries(const std::string& directory, double interval, double end_time);

  void start(Stepper& stepper) override;
  void resume(Stepper& stepper, const io::RunProgress& progress) override;
  void after_step(Stepper& stepper) override;
  void finish(Stepper& stepper) override;
  void save_progress(io::RunProgress& progress) const override;
  std::string last_state() const override;

private:
  void write(Stepper& stepper);

  std::string directory;
  OutputSchedule schedule;
  double last_time = -1.0; ///< s, of the newest mesh output
};
} // namespace vulnus::simulator
