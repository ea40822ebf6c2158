// Every run type (pure MPM, hybrid MPM-FE, pure FE) goes through the one time loop: the same
// files with the same meaning, the same report of a failed step (step, time, remedy, last
// good state, summary with completed = false), and the same answer to SIGTERM (history and
// summary kept; MPM also writes a checkpoint, tested in restart_tests).
#include "../app/command_runner.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <thread>

namespace
{
using namespace vulnus::testing;
namespace fs = std::filesystem;

struct RunType
{
  std::string name;
  std::string deck; ///< under inputs/
  std::string short_run; ///< --set entries for a run of a few steps
  bool particles;
  bool mesh;
};

/// The coarse scenes, cheapened: a rigid bullet and a 2 mm grid for the MPM side.
const std::vector<RunType> run_types = {
  {"mpm", "paper/anisotropic_150ms_coarse.prm",
   "--set 'Material bullet/Model=rigid' --set 'Grid/Cell size=0.002' --set 'Time/End time=1e-5' "
   "--set 'Output/Particle output interval=0'",
   true, false},
  {"hybrid", "paper/anisotropic_150ms_coarse_hybrid.prm",
   "--set 'Material bullet/Model=rigid' --set 'Time/End time=4e-6' "
   "--set 'Output/Particle output interval=0'",
   true, true},
  {"fe", "verification/fe_slab_pulse.prm", "--set 'Time/End time=2e-4'", false, true}};

void PrintTo(const RunType& type, std::ostream* out) { *out << type.name; }

std::string deck_of(const RunType& type)
{
  return "'" + source_dir() + "/inputs/" + type.deck + "' ";
}

nlohmann::json summary_of(const fs::path& run)
{
  return nlohmann::json::parse(read_text(run / "summary.json"));
}

/// history.csv: its header and the number of data rows.
std::pair<std::string, std::size_t> history_of(const fs::path& run)
{
  std::istringstream lines(read_text(run / "history.csv"));
  std::string header, line;
  std::getline(lines, header);
  std::size_t rows = 0;
  while (std::getline(lines, line))
    rows += !line.empty();
  return {header, rows};
}

class EveryRunType : public ::testing::TestWithParam<RunType>
{
};

TEST_P(EveryRunType, WritesTheSameFilesWithTheSameMeaning)
{
  const RunType& type = GetParam();
  ScratchDirectory scratch("run_type_files_" + type.name);
  const CommandResult r =
    run_vulnus("run " + deck_of(type) + type.short_run + " --output run", scratch.path);
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  const fs::path run = scratch.path / "run";
  for (const char* file : {"deck_used.prm", "log.txt", "history.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(run / file)) << file;
  EXPECT_EQ(fs::exists(run / "particles.xdmf"), type.particles);
  EXPECT_EQ(fs::exists(run / "fe_mesh.xdmf"), type.mesh);

  const nlohmann::json s = summary_of(run);
  for (const char* key : {"method", "completed", "steps", "time_s", "wall_seconds", "warnings",
                          "particles", "fe_cells", "mpi", "energy"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_TRUE(s["completed"].get<bool>());
  EXPECT_TRUE(s["energy"].contains("balance_error"));
  EXPECT_TRUE(s["energy"].contains("kinetic_J"));
  EXPECT_TRUE(s["energy"].contains("strain_J"));

  const auto [header, rows] = history_of(run);
  EXPECT_EQ(header.rfind("time_s,dt_s,step,kinetic_J,strain_J,", 0), 0u) << header;
  EXPECT_NE(header.find(",energy_balance_error,"), std::string::npos) << header;
  EXPECT_GE(rows, 2u); // the initial and the final state
}

TEST_P(EveryRunType, ReportsAFailedStepWithItsPlaceRemedyAndLastGoodState)
{
  const RunType& type = GetParam();
  ScratchDirectory scratch("run_type_failure_" + type.name);
  // MPM sides: a minimum step above the stable step (CFL 0.4 h / 150 m/s: 5.3e-6 s on the
  // pure-MPM 2 mm grid, 2.7e-6 s on the hybrid's 1 mm grid) and below the end time (which the
  // deck check requires) stops the first step. FE: a load that inverts the elements.
  const std::string failing = type.name == "fe"       ? "--set 'Far field/Load value=0,500,0'"
                              : type.name == "hybrid" ? "--set 'Time/Minimum time step=3.5e-6'"
                                                      : "--set 'Time/Minimum time step=8e-6'";
  const CommandResult r = run_vulnus(
    "run " + deck_of(type) + type.short_run + " " + failing + " --output run", scratch.path);
  EXPECT_EQ(r.exit_status, 1) << r.out << r.err;
  EXPECT_NE(r.err.find(" at step "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("likely remedy: "), std::string::npos) << r.err;
  // The MPM sides' collapsed step names its own remedy, spelled as deck entries; the FE
  // breakdown has no specific one and gets the run type's generic remedy.
  EXPECT_NE(r.err.find(type.name == "fe" ? "likely remedy: a smaller Far field/CFL"
                                         : "likely remedy: a smaller Time/CFL (or Time/Minimum"),
            std::string::npos)
    << r.err;
  EXPECT_EQ(r.err.find('{'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("likely remedy: ", r.err.find("likely remedy: ") + 1), std::string::npos)
    << r.err;
  EXPECT_NE(r.err.find("the last good state is "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Stacktrace"), std::string::npos) << r.err;
  const nlohmann::json s = summary_of(scratch.path / "run");
  EXPECT_FALSE(s["completed"].get<bool>());
  EXPECT_NE(s["error"].get<std::string>().find(" at step "), std::string::npos) << s["error"];
  if (type.name != "fe")
  {
    EXPECT_NE(s["error"].get<std::string>().find("below Time/Minimum time step"), std::string::npos)
      << s["error"];
  }
  EXPECT_GE(history_of(scratch.path / "run").second, 1u);
}

TEST_P(EveryRunType, StopsOnSigtermWithItsRecords)
{
  const RunType& type = GetParam();
  ScratchDirectory scratch("run_type_sigterm_" + type.name);
  // Long enough never to finish before the signal.
  const pid_t pid = start_vulnus(deck_of(type) + type.short_run +
                                   " --set 'Time/End time=1' --set 'Time/Stop when projectile exits=false'"
                                   " --output run",
                                 scratch.path, "run");
  ASSERT_GT(pid, 0);
  const fs::path history = scratch.path / "run" / "history.csv";
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (!fs::exists(history) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::seconds(1)); // some steps
  kill(pid, SIGTERM);
  int signal = 0;
  const int status = wait_for(pid, signal);
  EXPECT_EQ(status, 128 + SIGTERM) << read_text(scratch.path / "run.err");
  const std::string err = read_text(scratch.path / "run.err");
  EXPECT_NE(err.find("stopped by SIGTERM"), std::string::npos) << err;
  EXPECT_GE(history_of(scratch.path / "run").second, 1u);
  // Every run type checkpoints and says how to continue (restart_tests continues them).
  EXPECT_NE(err.find("--restart"), std::string::npos) << err;
}

INSTANTIATE_TEST_SUITE_P(RunTypes, EveryRunType, ::testing::ValuesIn(run_types),
                         [](const ::testing::TestParamInfo<RunType>& info) {
                           return info.param.name;
                         });
} // namespace
