// FE mesh outputs on the schedule.
#include "simulator/mesh_series.h"

#include "fem/far_field_solver.h"

#include <sstream>
#include <stdexcept>

namespace vulnus::simulator
{
MeshSeries::MeshSeries(const std::string& directory, const double interval, const double end_time)
    : directory(directory), schedule(interval, end_time)
{
}

void MeshSeries::write(Stepper& stepper)
{
  stepper.fe_side()->write_output(directory);
  last_time = stepper.time();
}

void MeshSeries::start(Stepper& stepper) { write(stepper); }

void MeshSeries::resume(Stepper&, const io::RunProgress& progress)
{
  // The far field's own checkpoint holds the XDMF records; the schedule is the particles'.
  schedule.set_next_time(progress.next_output);
}

void MeshSeries::save_progress(io::RunProgress& progress) const
{
  progress.next_output = schedule.next_time(); // the particles' schedule too, when both exist
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
  if (stepper.time() != last_time)
    write(stepper);
}

std::string MeshSeries::last_state() const
{
  std::ostringstream o;
  o << "the last FE mesh output (t = " << last_time << " s) in " << directory << "/fe_mesh.xdmf";
  return o.str();
}
} // namespace vulnus::simulator
