// Particle outputs on the schedule; their records travel with the checkpoints.
#include "simulator/particle_series.h"

#include "io/disk_space.h"
#include "mpm/solver.h"
#include "simulator/mpm_snapshot.h"

#include <sstream>

namespace vulnus::simulator
{
ParticleSeries::ParticleSeries(const std::string& directory, const double interval,
                               const MPI_Comm communicator)
    : directory(directory), output(directory, "particles", communicator), schedule(interval)
{
}

void ParticleSeries::write(const Stepper& stepper)
{
  // About 160 bytes a point: position, velocity, stress, fiber, flags and ids.
  constexpr double bytes_per_point = 160.0;
  const double n_points = double(stepper.mpm_side()->n_points_all_ranks()); // collective
  std::ostringstream what;
  what << "the particle output at t = " << stepper.time() << " s";
  io::require_free_space(directory, bytes_per_point * n_points, what.str());
  output.write(stepper.time(), mpm_snapshot(*stepper.mpm_side()));
}

void ParticleSeries::start(Stepper& stepper) { write(stepper); }

void ParticleSeries::resume(Stepper& stepper, const io::RunProgress& progress)
{
  std::istringstream records(progress.output_records);
  output.restore_records(records);
  schedule.resume(progress.next_output, stepper.time());
}

void ParticleSeries::after_step(Stepper& stepper)
{
  if (schedule.due(stepper.time()))
  {
    write(stepper);
    schedule.advance();
  }
}

void ParticleSeries::finish(Stepper& stepper)
{
  if (!output.has_output_at(stepper.time()))
    write(stepper);
}

void ParticleSeries::save_progress(io::RunProgress& progress) const
{
  progress.next_output = schedule.next_time();
  std::ostringstream records;
  output.save_records(records);
  progress.output_records = records.str();
}

std::string ParticleSeries::last_state() const
{
  std::ostringstream o;
  o << "the last particle output (t = " << output.last_time() << " s) in " << output.xdmf_path();
  return o.str();
}
} // namespace vulnus::simulator
