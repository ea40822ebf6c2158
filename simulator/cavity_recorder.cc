// Sampling the temporary cavity during the run and writing it into summary.json.
#include "simulator/cavity_recorder.h"

namespace vulnus::simulator
{
void CavityRecorder::start(Stepper& stepper)
{
  cavity = analysis::TemporaryCavity(*stepper.mpm_side());
  cavity.sample(*stepper.mpm_side());
}

void CavityRecorder::resume(Stepper&, const io::RunProgress& progress)
{
  if (!progress.cavity_record.empty())
    cavity.unpack(progress.cavity_record);
}

void CavityRecorder::after_step(Stepper& stepper)
{
  if (stepper.step_count() % interval == 0)
    cavity.sample(*stepper.mpm_side());
}

void CavityRecorder::finish(Stepper& stepper)
{
  cavity.sample(*stepper.mpm_side());
}

void CavityRecorder::save_progress(io::RunProgress& progress) const
{
  progress.cavity_record = cavity.active() ? cavity.packed() : std::vector<double>();
}

void CavityRecorder::add_to_summary(nlohmann::json& summary) const
{
  if (!cavity.active())
    return;
  nlohmann::json depth = nlohmann::json::array(), largest = nlohmann::json::array(),
                 when = nlohmann::json::array(), now = nlohmann::json::array(),
                 inside = nlohmann::json::array();
  for (const analysis::TemporaryCavity::Slice& s : cavity.profile())
  {
    depth.push_back(s.depth);
    largest.push_back(s.max_diameter);
    when.push_back(s.max_time);
    now.push_back(s.diameter);
    inside.push_back(s.inside_target);
  }
  const analysis::TemporaryCavity::Slice& peak = cavity.largest();
  summary["temporary_cavity"] = {{"slice_thickness_m", cavity.slice_thickness()},
                                 {"resolution_floor_m", cavity.resolution_floor()},
                                 {"sectors", analysis::TemporaryCavity::sectors},
                                 {"depth_m", depth},
                                 {"max_diameter_m", largest},
                                 {"max_time_s", when},
                                 {"diameter_now_m", now},
                                 {"inside_target", inside},
                                 {"largest",
                                  {{"diameter_m", peak.max_diameter},
                                   {"depth_m", peak.depth},
                                   {"time_s", peak.max_time}}}};
}
} // namespace vulnus::simulator
