// Checkpoint and restart through `vulnus run`: a run killed mid-way (SIGKILL, no chance to
// clean up) or stopped (SIGTERM, writes a checkpoint and exits 143) and restarted with
// `--restart` ends bit for bit like the uninterrupted run on the same thread count; a
// half-written newest checkpoint is skipped; a deck that changed the physics is refused.
#include "../app/command_runner.h"
#include "run_comparison.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <thread>
#include <unistd.h>

namespace
{
using namespace vulnus::testing;
namespace fs = std::filesystem;

/// The coarse paper scene's slab cut to 20 x 10 x 20 mm (grid and fixed side faces with it:
/// 39 thousand points instead of 207 thousand; a restart's equality does not depend on the
/// slab's width, and the tissue's waves, about 14 m/s, cross 1.4 mm in the run).
const std::string narrow_slab = " --set 'Grid/Domain min=-0.01, -0.02, -0.01'"
                                " --set 'Grid/Domain max=0.01, 0.035, 0.01'"
                                " --set 'Body slab/Box min=-0.01, 0, -0.01'"
                                " --set 'Body slab/Box max=0.01, 0.01, 0.01'";

/// The narrowed coarse paper scene with a rigid bullet to 1e-4 s (about 80 steps), two
/// threads, a checkpoint every 5 steps and particle outputs every 2e-5 s.
std::string scene_arguments(const std::string& extra = "")
{
  return "'" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse.prm' --threads 2" +
         narrow_slab + " --set 'Material bullet/Model=rigid' --set 'Time/End time=1e-4'" +
         " --set 'Output/Particle output interval=2e-5' --set 'Output/Checkpoint step interval=5' " +
         extra;
}

std::size_t n_checkpoints(const fs::path& run)
{
  std::size_t n = 0;
  if (fs::is_directory(run / "checkpoints"))
    for (const auto& entry : fs::directory_iterator(run / "checkpoints"))
      n += entry.path().extension() == ".chk";
  return n;
}

/// The hybrid version of the same scene (the +-11 mm zone, explicit far field, multi step) on
/// a 2 mm grid (the zone's bounds are nodes of it; 5.8 thousand zone points, and a far field
/// meshed from 2 mm at the interface, whose implicit windows' interface mass is probed with
/// several times cheaper solves), to 1e-4 s (about 40 steps), every checkpoint kept. A far-field
/// point the coarser wound reaches does not stop the run: the restart's equality is tested.
std::string hybrid_arguments(const std::string& extra = "")
{
  return "'" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse_hybrid.prm' --threads 2" +
         " --set 'Material bullet/Model=rigid' --set 'Grid/Cell size=0.002' --set 'Time/End time=1e-4'" +
         " --set 'Hybrid/Stop when FE points fail=false'" +
         " --set 'Output/Particle output interval=2e-5' --set 'Output/Checkpoint step interval=5'" +
         " --set 'Output/Checkpoints kept=1000' " + extra;
}

/// Starts a run and sends `signal` once it has written its first checkpoint.
void interrupt_after_first_checkpoint(const fs::path& scratch, const std::string& run, const int signal,
                                      int& exit_status, int& killed_by,
                                      std::string (*arguments)(const std::string&) = scene_arguments)
{
  const pid_t pid = start_vulnus(arguments("--output " + run), scratch, run);
  ASSERT_GT(pid, 0);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (n_checkpoints(scratch / run) == 0 && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, signal);
  exit_status = wait_for(pid, killed_by);
}

/// Same summary, history and final particle state, to the bit.
void expect_identical_runs(const fs::path& reference, const fs::path& restarted)
{
  EXPECT_EQ(summary_without_timing(reference), summary_without_timing(restarted));
  EXPECT_EQ(read_text(reference / "history.csv"), read_text(restarted / "history.csv"));
  EXPECT_EQ(read_text(reference / "particles.xdmf"), read_text(restarted / "particles.xdmf"));
  // The state the checkpoint carries: positions, velocities, the stress (from F and the
  // failure state), the displacement and the failure flags.
  for (const char* field : {"positions", "velocity", "stress", "displacement", "failure"})
  {
    const std::vector<double> expected = dataset(reference / "particles_00005.h5", field);
    EXPECT_FALSE(expected.empty()) << field;
    EXPECT_EQ(expected, dataset(restarted / "particles_00005.h5", field)) << field;
  }
}

// The five checks below share one reference run. (As TEST_Fs of a suite whose
// SetUpTestSuite ran the reference, each re-ran it: CTest starts one process per discovered
// test.) Each check is its own function, so a failed ASSERT ends that check only.
void expect_a_killed_run_to_continue_bit_for_bit(const fs::path& scratch)
{
  int status = 0, signal = 0;
  interrupt_after_first_checkpoint(scratch, "killed", SIGKILL, status, signal);
  ASSERT_EQ(signal, SIGKILL) << "the run ended before it could be killed";
  EXPECT_FALSE(fs::exists(scratch / "killed" / "summary.json"));

  const CommandResult r = run_vulnus("run " + scene_arguments("--restart killed"), scratch);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("restarted from"), std::string::npos);
  expect_identical_runs(scratch / "reference", scratch / "killed");
}

void expect_sigterm_to_checkpoint_and_the_run_to_continue_bit_for_bit(const fs::path& scratch)
{
  int status = 0, signal = 0;
  interrupt_after_first_checkpoint(scratch, "stopped", SIGTERM, status, signal);
  ASSERT_EQ(signal, 0);
  ASSERT_EQ(status, 128 + SIGTERM) << "the run ended before the signal came";
  const std::string err = read_text(scratch / "stopped.err");
  EXPECT_NE(err.find("stopped by SIGTERM"), std::string::npos) << err;
  EXPECT_NE(err.find("--restart stopped"), std::string::npos) << err;

  const CommandResult r = run_vulnus("run " + scene_arguments("--restart stopped"), scratch);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  expect_identical_runs(scratch / "reference", scratch / "stopped");
}

void expect_a_half_written_newest_checkpoint_to_be_skipped(const fs::path& scratch)
{
  // The reference run kept its two newest checkpoints; a torn copy named as a later step and
  // a temporary file of an interrupted write must not be taken.
  const fs::path run = scratch / "torn";
  fs::copy(scratch / "reference", run, fs::copy_options::recursive);
  const fs::path newest = *fs::directory_iterator(run / "checkpoints"); // any complete one
  fs::copy_file(newest, run / "checkpoints" / "step_9999999999.chk");
  fs::resize_file(run / "checkpoints" / "step_9999999999.chk", fs::file_size(newest) / 2);
  write_text(run / "checkpoints" / "step_9999999998.chk.tmp", "half");
  fs::remove(run / "summary.json");

  const CommandResult r = run_vulnus("run " + scene_arguments("--restart torn"), scratch);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.err.find("step_9999999999.chk' skipped: checkpoint is truncated"), std::string::npos)
    << r.err;
  EXPECT_EQ(r.err.find("9999999998"), std::string::npos) << r.err;
  expect_identical_runs(scratch / "reference", run);
}

void expect_changed_physics_to_be_refused_naming_the_entry(const fs::path& scratch)
{
  const fs::path run = scratch / "changed";
  fs::copy(scratch / "reference", run, fs::copy_options::recursive);
  const CommandResult r = run_vulnus(
    "run " + scene_arguments("--restart changed --set 'Material tissue/Transversely isotropic hyperelastic/c1=2000'"), scratch);
  EXPECT_EQ(r.exit_status, 2); // an input error, like a bad deck
  EXPECT_NE(r.err.find("Material tissue/Transversely isotropic hyperelastic/c1: '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'2000' in the deck"), std::string::npos) << r.err;
  // A longer end time or a smaller CFL is a continuation, not another scene.
  const CommandResult longer = run_vulnus(
    "run " + scene_arguments("--restart changed --set 'Time/End time=1.1e-4' --set 'Time/CFL=0.3'"),
    scratch);
  EXPECT_EQ(longer.exit_status, 0) << longer.err;
}

// A restart that leaves out one of the run's --set entries (here the rigid bullet) names
// that entry; restoring first called every good checkpoint "inconsistent". (The narrowing
// entries stay: the first difference in path order is named, and they sort before it.)
void expect_a_forgotten_set_entry_to_be_named(const fs::path& scratch)
{
  const fs::path run = scratch / "forgotten";
  fs::copy(scratch / "reference", run, fs::copy_options::recursive);
  const CommandResult r = run_vulnus(
    "run '" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse.prm' --threads 2" +
    narrow_slab + " --set 'Time/End time=1e-4' --restart forgotten", scratch);
  EXPECT_EQ(r.exit_status, 2) << r.err;
  EXPECT_NE(r.err.find("Material bullet/Model"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("inconsistent"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("skipped"), std::string::npos) << r.err;
}

TEST(Restart, KilledStoppedTornChangedAndForgottenRunsAgainstOneReference)
{
  ScratchDirectory scratch("restart");
  const CommandResult r = run_vulnus("run " + scene_arguments("--output reference"), scratch.path);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  {
    SCOPED_TRACE("killed run continues bit for bit");
    expect_a_killed_run_to_continue_bit_for_bit(scratch.path);
  }
  {
    SCOPED_TRACE("SIGTERM writes a checkpoint and the run continues bit for bit");
    expect_sigterm_to_checkpoint_and_the_run_to_continue_bit_for_bit(scratch.path);
  }
  {
    SCOPED_TRACE("half-written newest checkpoint is skipped");
    expect_a_half_written_newest_checkpoint_to_be_skipped(scratch.path);
  }
  {
    SCOPED_TRACE("changed physics is refused naming the entry");
    expect_changed_physics_to_be_refused_naming_the_entry(scratch.path);
  }
  {
    SCOPED_TRACE("a forgotten --set entry is named");
    expect_a_forgotten_set_entry_to_be_named(scratch.path);
  }
}

// A run to its end in `reference`, the same run killed after its first checkpoint in
// `killed` and restarted there: the restart's result (a failure of the first two steps is
// reported as a failed restart, exit status -1).
template <class Arguments>
CommandResult reference_then_killed_and_restarted(const fs::path& directory, Arguments arguments)
{
  const CommandResult reference = run_vulnus("run " + arguments("--output reference"), directory);
  EXPECT_EQ(reference.exit_status, 0) << reference.err;
  int status = 0, signal = 0;
  interrupt_after_first_checkpoint(directory, "killed", SIGKILL, status, signal, arguments);
  EXPECT_EQ(signal, SIGKILL) << "the run ended before it could be killed";
  if (reference.exit_status != 0 || signal != SIGKILL)
    return CommandResult{};
  return run_vulnus("run " + arguments("--restart killed"), directory);
}

// A run to its end in `reference` (every checkpoint kept), copied to `restarted` with what was
// written after its second checkpoint removed (later checkpoints, particle files, the summary)
// and a stray last history row, and restarted there: the restart's result. No race with the
// run (unlike a kill), and no second run up to the first checkpoint.
template <class Arguments>
CommandResult reference_then_restarted_from_second_checkpoint(const fs::path& directory,
                                                              Arguments arguments)
{
  const CommandResult reference = run_vulnus("run " + arguments("--output reference"), directory);
  EXPECT_EQ(reference.exit_status, 0) << reference.err;
  if (reference.exit_status != 0)
    return CommandResult{};
  const fs::path run = directory / "restarted";
  fs::copy(directory / "reference", run, fs::copy_options::recursive);
  std::vector<fs::path> checkpoints;
  for (const auto& entry : fs::directory_iterator(run / "checkpoints"))
    if (entry.path().extension() == ".chk")
      checkpoints.push_back(entry.path());
  std::sort(checkpoints.begin(), checkpoints.end());
  EXPECT_GE(checkpoints.size(), 3u);
  if (checkpoints.size() < 3)
    return CommandResult{};
  for (std::size_t k = 2; k < checkpoints.size(); ++k)
    fs::remove(checkpoints[k]);
  for (const auto& entry : fs::directory_iterator(directory / "reference"))
  {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".h5" && name.rfind("particles_", 0) == 0 &&
        name != "particles_00000.h5")
      fs::remove(run / name);
  }
  fs::remove(run / "summary.json");
  std::ofstream(run / "history.csv", std::ios::app) << "stray row of a killed run\n";
  return run_vulnus("run " + arguments("--restart restarted"), directory);
}

// A hybrid run restarted from a mid-run checkpoint continues bit for bit: the MPM zone, the far
// field (vectors, quadrature-point histories, mesh output records) and the coupling's window
// state, with the explicit far field and with the implicit ones (Newmark's and generalized
// alpha's displacement, velocity, acceleration and previous forces). (A killed hybrid run:
// AdaptiveZoneRestart.)
class HybridRestart : public ::testing::TestWithParam<const char*>
{
};

std::string far_field_arguments(const std::string& extra)
{
  return hybrid_arguments("--set 'Far field/Integrator=" + std::string(HybridRestart::GetParam()) +
                          "' " + extra);
}

TEST_P(HybridRestart, RestartedRunContinuesBitForBit)
{
  ScratchDirectory scratch("hybrid_restart");
  const CommandResult r =
    reference_then_restarted_from_second_checkpoint(scratch.path, far_field_arguments);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("restarted from"), std::string::npos);
  expect_identical_runs(scratch.path / "reference", scratch.path / "restarted");
  EXPECT_EQ(read_text(scratch.path / "reference" / "fe_mesh.xdmf"),
            read_text(scratch.path / "restarted" / "fe_mesh.xdmf"));
}

INSTANTIATE_TEST_SUITE_P(Integrators, HybridRestart,
                         ::testing::Values("central difference", "Newmark", "generalized alpha"),
                         [](const auto& info)
                         {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), ' ', '_');
                           return name;
                         });

/// The adaptive-zone deck on stiff tissue (K = 100 MPa, rigid bullet): the zone first grows
/// at step 85, before the first checkpoint (step 100).
std::string adaptive_arguments(const std::string& extra)
{
  return "'" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse_adaptive.prm' --threads 2" +
         " --set 'Material bullet/Model=rigid' --set 'Time/End time=1e-4'" +
         " --set 'Material tissue/Transversely isotropic hyperelastic/Bulk modulus=1e8'" +
         " --set 'Output/Particle output interval=2e-5' --set 'Output/Checkpoint step interval=100' " +
         extra;
}

// Killed after its zone has grown, the run restarts on the grown zone's far field and
// continues (with its later conversions) bit for bit.
TEST(AdaptiveZoneRestart, KilledAfterAConversionContinuesBitForBit)
{
  ScratchDirectory scratch("adaptive_restart");
  const CommandResult r = reference_then_killed_and_restarted(scratch.path, adaptive_arguments);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("restarted from"), std::string::npos);
  const nlohmann::json summary =
    nlohmann::json::parse(read_text(scratch.path / "reference" / "summary.json"));
  const nlohmann::json& conversions = summary["hybrid"]["adaptive_zone"]["conversions"];
  ASSERT_GE(conversions.size(), 2u);
  EXPECT_LT(conversions[0]["mpm_step"].get<int>(), 100); // before the checkpoint
  EXPECT_GT(conversions.back()["mpm_step"].get<int>(), 100); // and after it
  expect_identical_runs(scratch.path / "reference", scratch.path / "killed");
  EXPECT_EQ(read_text(scratch.path / "reference" / "fe_mesh.xdmf"),
            read_text(scratch.path / "killed" / "fe_mesh.xdmf"));
}

/// The pure-FE pulse deck with a checkpoint every 5 steps.
std::string fe_arguments(const std::string& extra = "")
{
  return "'" + source_dir() + "/inputs/verification/fe_slab_pulse.prm'" +
         " --set 'Output/Checkpoint step interval=5' " + extra;
}

TEST(FeRestart, KilledRunContinuesBitForBit)
{
  ScratchDirectory scratch("fe_restart");
  const CommandResult r = reference_then_killed_and_restarted(scratch.path, fe_arguments);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_EQ(summary_without_timing(scratch.path / "reference"),
            summary_without_timing(scratch.path / "killed"));
  for (const char* file : {"history.csv", "fe_mesh.xdmf"})
    EXPECT_EQ(read_text(scratch.path / "reference" / file), read_text(scratch.path / "killed" / file))
      << file;
}

TEST(RestartRefusals, NoCheckpointHybridAndOutputTogether)
{
  ScratchDirectory scratch("restart_refusals");
  fs::create_directories(scratch.path / "empty");
  CommandResult r = run_vulnus("run " + scene_arguments("--restart empty"), scratch.path);
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("no checkpoint in 'empty/checkpoints'"), std::string::npos) << r.err;

  // A hybrid run restarts like a pure one: without checkpoints it says so.
  r = run_vulnus("run '" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse_hybrid.prm' --restart empty",
                 scratch.path);
  EXPECT_EQ(r.exit_status, 1);
  EXPECT_NE(r.err.find("no checkpoint in 'empty/checkpoints'"), std::string::npos) << r.err;

  // Checkpoints of a 2-rank run restarted on one process: the counts named, exit 2.
  fs::create_directories(scratch.path / "two_ranks" / "checkpoints" / "rank_0");
  fs::create_directories(scratch.path / "two_ranks" / "checkpoints" / "rank_1");
  r = run_vulnus("run " + scene_arguments("--restart two_ranks"), scratch.path);
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("written by a run on 2 MPI ranks, this run has 1 process"), std::string::npos)
    << r.err;
  EXPECT_NE(r.err.find("mpirun -np 2"), std::string::npos) << r.err;

  r = run_vulnus("run deck.prm --restart a --output b", scratch.path);
  EXPECT_EQ(r.exit_status, 2);
  EXPECT_NE(r.err.find("cannot be combined with --output"), std::string::npos) << r.err;
}
} // namespace
