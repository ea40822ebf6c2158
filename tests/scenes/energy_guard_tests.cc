// The energy guard: a run whose energy balance breaks warns at the step it was first seen
// (with the likely causes), or stops as a blow-up past the limit with its records kept; a
// sound run says nothing. The broken scene: an elastic-plastic bullet into a
// prescribed rigid slab. Without the shock viscosity and the projectile's relaxation it gains
// 32 % of its energy; with them it gains 7.7 % by 120 microseconds
// (5 % at step 140) at CFL 0.4 when the bullet steps with the scene, so the tests run at that
// step without subcycling and set bounds below that. (Subcycled, the same scene closes its
// balance to 1e-4: the contact's work on the bullet is booked over its substeps.) A restart
// keeps the warning given before its checkpoint.
#include "../app/command_runner.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace
{
using namespace vulnus::testing;
namespace fs = std::filesystem;

const std::string paper_deck = "run '" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse.prm' ";

/// The bullet driven into a wall that cannot move or deform: the balance error grows to 0.022 in
/// the impact's first 14 us and ends at 0.032 (0.077 with the contact's correction booked at the trial velocities).
/// The wall and grid are cut to +-10 / +-12 mm across the flight (4 thousand wall points instead
/// of 25 thousand): the prescribed wall acts only where the bullet (radius 4.5 mm, mushrooming
/// to about 7) touches it. [TO CHECK when first run: the two figures above on this wall.]
const std::string bullet_into_wall =
  paper_deck + "--set 'Grid/Cell size=0.002' --set 'Material tissue/Model=rigid' "
               "--set 'Body slab/Rigid motion=prescribed' --set 'Time/End time=1.2e-4' "
               "--set 'Grid/Domain min=-0.012, -0.02, -0.012' --set 'Grid/Domain max=0.012, 0.035, 0.012' "
               "--set 'Body slab/Box min=-0.01, 0, -0.01' --set 'Body slab/Box max=0.01, 0.01, 0.01' "
               "--set 'Output/Particle output interval=0' --set 'Time/CFL=0.4' "
               "--set 'Time/Subcycle projectile=false' ";

nlohmann::json summary_of(const fs::path& run)
{
  return nlohmann::json::parse(read_text(run / "summary.json"));
}

std::string energy_warning_of(const nlohmann::json& summary)
{
  for (const auto& w : summary["warnings"])
    if (w.get<std::string>().find("energy balance error") != std::string::npos)
      return w.get<std::string>();
  return "";
}
} // namespace

TEST(EnergyGuard, StopsARunPastTheLimitAsABlowUp)
{
  ScratchDirectory scratch("energy_guard_stop");
  const CommandResult r = run_vulnus(bullet_into_wall +
                                       "--set 'Time/Energy balance warning=0.01' "
                                       "--set 'Time/Energy balance limit=0.02' --output run",
                                     scratch.path);
  EXPECT_EQ(r.exit_status, 1) << r.out << r.err;
  const nlohmann::json summary = summary_of(scratch.path / "run");
  EXPECT_FALSE(summary["completed"].get<bool>());
  const std::string error = summary["error"].get<std::string>();
  EXPECT_NE(error.find("blow-up at step"), std::string::npos) << error;
  EXPECT_NE(error.find("Energy balance limit = 0.02"), std::string::npos) << error;
  EXPECT_EQ(error.find("energy balance error", error.find("energy balance error") + 1),
            std::string::npos) << error; // said once
  EXPECT_NE(error.find("likely causes"), std::string::npos) << error;
  // It warned first, at a smaller error, and the history holds the steps up to the stop.
  EXPECT_NE(energy_warning_of(summary).find("Energy balance warning = 0.01"), std::string::npos);
  EXPECT_TRUE(fs::exists(scratch.path / "run" / "history.csv"));
  EXPECT_NE((r.out + r.err).find("the last good state is"), std::string::npos) << r.out << r.err;
}

TEST(EnergyGuard, WarnsOnceWhenOnlyTheWarningIsSet)
{
  ScratchDirectory scratch("energy_guard_warn");
  const CommandResult r = run_vulnus(
    bullet_into_wall + "--set 'Time/Energy balance warning=0.02' "
                       "--set 'Time/Energy balance limit=0' --output run",
    scratch.path);
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  const nlohmann::json summary = summary_of(scratch.path / "run");
  EXPECT_TRUE(summary["completed"].get<bool>());
  const std::string warning = energy_warning_of(summary);
  EXPECT_NE(warning.find(" at step "), std::string::npos) << warning;
  EXPECT_NE(warning.find("gained energy"), std::string::npos) << warning;
  // The balance it warned about is in the summary too, beyond the bound.
  EXPECT_GT(std::abs(summary["energy"]["balance_error"].get<double>()), 0.02);
  std::size_t n_energy_warnings = 0;
  for (const auto& w : summary["warnings"])
    n_energy_warnings += w.get<std::string>().find("energy balance error") != std::string::npos;
  EXPECT_EQ(n_energy_warnings, 1u);
}

TEST(EnergyGuard, ASoundRunSaysNothing)
{
  ScratchDirectory scratch("energy_guard_sound");
  const CommandResult r = run_vulnus(paper_deck + "--set 'Material bullet/Model=rigid' "
                                     "--set 'Grid/Cell size=0.002' --set 'Time/End time=6e-5' "
                                     "--set 'Output/Particle output interval=0' --output run",
                                     scratch.path);
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const nlohmann::json summary = summary_of(scratch.path / "run");
  EXPECT_LT(std::abs(summary["energy"]["balance_error"].get<double>()), 0.05);
  EXPECT_EQ(energy_warning_of(summary), "");
}

TEST(EnergyGuard, BoundsInTheWrongOrderAreRefused)
{
  ScratchDirectory scratch("energy_guard_bounds");
  const CommandResult r =
    run_vulnus(paper_deck + "--set 'Time/Energy balance warning=0.5' --output run", scratch.path);
  EXPECT_EQ(r.exit_status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("Time/Energy balance warning, Time/Energy balance limit"), std::string::npos)
    << r.err;
}

TEST(EnergyGuard, AMinimumStepBeyondTheEndTimeIsRefused)
{
  ScratchDirectory scratch("energy_guard_min_step");
  const CommandResult r =
    run_vulnus(paper_deck + "--set 'Time/Minimum time step=1e-3' --output run", scratch.path);
  EXPECT_EQ(r.exit_status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("Time/Minimum time step"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("must be below Time/End time"), std::string::npos) << r.err;
  // The suggested value lies below the deck's end time (4e-4 s), not at a fixed 1e-12.
  EXPECT_NE(r.err.find("lower it, e.g. 4e-07"), std::string::npos) << r.err;
}

// A velocity pulse on a face that takes back what it put in (a soft slab, K = 10 MPa, pulled
// at up to 2.3 m/s for 0.8 ms: the wave returns and the face absorbs it) leaves the load's net
// work near zero. Measured against it, the round-off of a sound run read as -0.40 and stopped
// the run as a blow-up at 0.73 ms (physics fuzzer, seed 540, scene 56); measured against the
// energy the load put in, the balance is 6e-4.
TEST(EnergyGuard, AFaceLoadThatTakesItsEnergyBackIsNoBlowUp)
{
  ScratchDirectory scratch("energy_guard_returned_load");
  const CommandResult r =
    run_vulnus("run '" + source_dir() + "/inputs/verification/fe_slab_pulse.prm' --threads 2 "
               "--set 'Material tissue/Transversely isotropic hyperelastic/Bulk modulus=1.035e7' "
               "--set 'Far field/Volume averaging=cell' --set 'Far field/Load value=0, -2.277, 0' "
               "--set 'Time/End time=8.4e-4' --set 'Output/Particle output interval=0' "
               "--output run",
               scratch.path);
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const nlohmann::json summary = summary_of(scratch.path / "run");
  const nlohmann::json& energy = summary["energy"];
  // The load gave back nearly all it put in.
  EXPECT_LT(energy["external_work_J"].get<double>(),
            0.01 * energy["external_work_in_J"].get<double>());
  EXPECT_LT(std::abs(energy["balance_error"].get<double>()), 0.005);
  EXPECT_EQ(energy_warning_of(summary), "");
}

// A restart keeps the warnings the run gave before its checkpoint: summary.json's warnings are
// the uninterrupted run's. The guard's flag was not in the checkpoint, so a restarted run lost
// its first crossing's warning (step 600, -0.050) and gave one at a later crossing (step 2860,
// -0.093) instead. Here the run continues from its newest checkpoint, after the warning.
TEST(EnergyGuard, ARestartKeepsTheWarningGivenBeforeTheCheckpoint)
{
  ScratchDirectory scratch("energy_guard_restart");
  const std::string arguments = bullet_into_wall + "--set 'Time/Energy balance warning=0.01' "
                                                   "--set 'Time/Energy balance limit=0' "
                                                   "--set 'Output/Checkpoint step interval=10' ";
  const CommandResult reference = run_vulnus(arguments + "--output reference", scratch.path);
  ASSERT_EQ(reference.exit_status, 0) << reference.out << reference.err;
  const nlohmann::json expected = summary_of(scratch.path / "reference");
  const std::string warning = energy_warning_of(expected);
  ASSERT_NE(warning.find(" at step "), std::string::npos) << warning;
  const long warned_at = std::stol(warning.substr(warning.find(" at step ") + 9));

  const fs::path run = scratch.path / "restarted";
  fs::copy(scratch.path / "reference", run, fs::copy_options::recursive);
  fs::remove(run / "summary.json");
  long newest = 0; // checkpoints/step_NNNNNNNNNN.chk
  for (const auto& entry : fs::directory_iterator(run / "checkpoints"))
    if (entry.path().extension() == ".chk")
      newest = std::max(newest, std::stol(entry.path().stem().string().substr(5)));
  ASSERT_GT(newest, warned_at);
  const CommandResult restarted = run_vulnus(arguments + "--restart restarted", scratch.path);
  ASSERT_EQ(restarted.exit_status, 0) << restarted.out << restarted.err;
  EXPECT_NE(restarted.out.find("restarted from"), std::string::npos) << restarted.out;
  EXPECT_EQ(summary_of(run)["warnings"], expected["warnings"]);
}
