// Warnings before the first step about scenes that run but may mislead: a target narrower
// than the projectile across its path (a 4 mm slab against a 9 mm bullet would report
// an "exit" with the plug still on the nose), nearly incompressible tissue whose points keep
// their own volume (they lock), an exact rigid surface a held projectile loses, and a supported
// domain face that no body reaches.
#include "../app/command_runner.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace
{
using namespace vulnus::testing;

const std::string short_paper_run =
  "run '" + source_dir() + "/inputs/paper/anisotropic_150ms_coarse.prm' --set "
  "'Material bullet/Model=rigid' --set 'Grid/Cell size=0.002' --set 'Time/End time=1e-5' "
  "--set 'Output/Particle output interval=0' ";

std::vector<std::string> warnings_of(const std::filesystem::path& run)
{
  const nlohmann::json s = nlohmann::json::parse(read_text(run / "summary.json"));
  return s["warnings"].get<std::vector<std::string>>();
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text)
{
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos)
      return true;
  return false;
}
} // namespace

TEST(SceneWarnings, ATargetNarrowerThanTheProjectileIsFlagged)
{
  ScratchDirectory scratch("scene_warning_narrow");
  const CommandResult narrow = run_vulnus(
    short_paper_run + "--set 'Body slab/Box min=-0.002, 0, -0.025' "
                      "--set 'Body slab/Box max=0.002, 0.01, 0.025' --output narrow",
    scratch.path);
  ASSERT_EQ(narrow.exit_status, 0) << narrow.out << narrow.err;
  EXPECT_TRUE(mentions(warnings_of(scratch.path / "narrow"),
                       "body 'slab' is 4 mm wide across the path of projectile 'bullet' "
                       "(diameter 9 mm)"));
  EXPECT_NE(narrow.err.find("describe a plug"), std::string::npos) << narrow.err;

  const CommandResult wide = run_vulnus(short_paper_run + "--output wide", scratch.path);
  ASSERT_EQ(wide.exit_status, 0) << wide.out << wide.err;
  EXPECT_FALSE(mentions(warnings_of(scratch.path / "wide"), "wide across the path"));
}

// A bullet flying partly out through a free domain face loses points to the grid's edge:
// the run says that what it reports of the bullet is only what stayed.
TEST(SceneWarnings, AProjectileLeavingTheGridInPartIsFlagged)
{
  ScratchDirectory scratch("scene_warning_partly_departed");
  const CommandResult r = run_vulnus(
    short_paper_run + "--set 'Body bullet/Center=0.02, -0.016, 0' "
                      "--set 'Body bullet/Initial velocity=80, 150, 0' "
                      "--set 'Grid/Boundary conditions/x+=free' --set 'Time/End time=1e-4' "
                      "--output run",
    scratch.path);
  ASSERT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_TRUE(mentions(warnings_of(scratch.path / "run"), "of the projectile's"))
    << r.err;
  EXPECT_NE(r.err.find("describe only the"), std::string::npos) << r.err;
}

// An elastic-plastic bullet stepped with the scene gives a wound that drifts with the step:
// the run says so and names the entry; subcycled it says nothing about it, nor when the
// bullet is held rigid while elastic (the default), which the log says instead.
TEST(SceneWarnings, AnUnsubcycledDeformableProjectileIsFlagged)
{
  ScratchDirectory scratch("scene_warning_unsubcycled");
  const std::string elastic_plastic_run = short_paper_run +
                                          "--set 'Material bullet/Model=elastic plastic' ";
  const std::string deformable = "--set 'Time/Rigid projectile while elastic=false' ";
  const CommandResult stepped =
    run_vulnus(elastic_plastic_run + deformable +
                 "--set 'Time/Subcycle projectile=false' --output stepped",
               scratch.path);
  ASSERT_EQ(stepped.exit_status, 0) << stepped.out << stepped.err;
  EXPECT_TRUE(mentions(warnings_of(scratch.path / "stepped"),
                       "not subcycled (Time/Subcycle projectile = false)"));
  const CommandResult subcycled =
    run_vulnus(elastic_plastic_run + deformable + "--output subcycled", scratch.path);
  ASSERT_EQ(subcycled.exit_status, 0) << subcycled.out << subcycled.err;
  EXPECT_FALSE(mentions(warnings_of(scratch.path / "subcycled"), "not subcycled"));
  EXPECT_NE(read_text(scratch.path / "subcycled" / "log.txt").find("subcycled: substeps"),
            std::string::npos);
  const CommandResult held = run_vulnus(
    elastic_plastic_run + "--set 'Time/Subcycle projectile=false' --output held", scratch.path);
  ASSERT_EQ(held.exit_status, 0) << held.out << held.err;
  EXPECT_FALSE(mentions(warnings_of(scratch.path / "held"), "not subcycled"));
  const std::string log = read_text(scratch.path / "held" / "log.txt");
  EXPECT_NE(log.find("held rigid while elastic: acoustic impact pressure"), std::string::npos);
  EXPECT_NE(log.find("projectile held rigid while elastic to the end: peak contact pressure"),
            std::string::npos);
}

TEST(SceneWarnings, NearlyIncompressibleTissueWithoutVolumeAveragingIsFlagged)
{
  // K / mu = 2.2e9 / 4200: points that keep their own J lock (docs/locking.md).
  ScratchDirectory scratch("scene_warning_locking");
  const std::string stiff =
    short_paper_run + "--set 'Material tissue/Transversely isotropic hyperelastic/Bulk modulus=2.2e9' "
                      "--set 'Time/End time=2e-7' ";
  const CommandResult own = run_vulnus(stiff + "--output own", scratch.path);
  ASSERT_EQ(own.exit_status, 0) << own.out << own.err;
  EXPECT_TRUE(mentions(warnings_of(scratch.path / "own"),
                       "body 'slab': material 'tissue' has bulk:shear 523810"));
  EXPECT_TRUE(mentions(warnings_of(scratch.path / "own"), "set Grid/Volume averaging = cell"));

  const CommandResult cell =
    run_vulnus(stiff + "--set 'Grid/Volume averaging=cell' --output cell", scratch.path);
  ASSERT_EQ(cell.exit_status, 0) << cell.out << cell.err;
  EXPECT_FALSE(mentions(warnings_of(scratch.path / "cell"), "bulk:shear"));
  // The bullet (bulk:shear 2.2) is not flagged.
  EXPECT_FALSE(mentions(warnings_of(scratch.path / "own"), "'bullet'"));
}

// Contact/Rigid surface = exact is a rigid body's: an elastic-plastic bullet held rigid while
// elastic takes it only until the hold releases it (here at the impact: the stress limit is set
// low), and its contact then takes its points. A held ball's velocity jumped from 116.25 to
// 110.7 m/s at that switch without a word; the log at the release and summary.json now say so.
// Whether the hold lasts is the run's to say: `vulnus check` warns only where the bullet is
// never held (and never takes the exact surface). A rigid bullet keeps it and draws no warning.
TEST(SceneWarnings, AnExactSurfaceTheHeldProjectileLosesAtItsReleaseIsSaid)
{
  ScratchDirectory scratch("scene_warning_exact_surface");
  const std::string exact = "--set 'Contact/Rigid surface=exact' ";
  const std::string deformable = short_paper_run + exact +
                                 "--set 'Material bullet/Model=elastic plastic' "
                                 "--set 'Time/End time=3e-5' ";
  const std::string released = deformable + "--set 'Time/Rigid projectile stress limit=0.01' ";
  const std::string start = "Contact/Rigid surface = exact: projectile 'bullet' has the "
                            "deformable law 'elastic plastic'";
  const CommandResult check = run_vulnus("check " + released.substr(4), scratch.path); // no "run"
  ASSERT_EQ(check.exit_status, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("deck OK"), std::string::npos) << check.out;
  EXPECT_EQ(check.err.find(start), std::string::npos) << check.err;
  const CommandResult never =
    run_vulnus("check " + deformable.substr(4) + "--set 'Time/Rigid projectile while elastic=false'",
               scratch.path);
  ASSERT_EQ(never.exit_status, 0) << never.out << never.err;
  EXPECT_NE(never.err.find("vulnus: warning: " + start + " and the exact surface is a rigid "
                           "body's: its contact takes its points throughout"),
            std::string::npos)
    << never.err;

  const CommandResult run = run_vulnus(released + "--output released", scratch.path);
  ASSERT_EQ(run.exit_status, 0) << run.out << run.err;
  const nlohmann::json summary =
    nlohmann::json::parse(read_text(scratch.path / "released" / "summary.json"));
  ASSERT_FALSE(summary["bullet"]["rigid_hold"]["release_step"].is_null()) << summary["bullet"];
  const std::vector<std::string> warnings = warnings_of(scratch.path / "released");
  EXPECT_TRUE(mentions(warnings, "took the exact surface only while held rigid while elastic, "
                                 "up to step " +
                                   std::to_string(summary["bullet"]["rigid_hold"]["release_step"]
                                                    .get<long>())));
  const std::string log = read_text(scratch.path / "released" / "log.txt");
  EXPECT_NE(log.find("its contact takes its points from here on, not the exact surface"),
            std::string::npos)
    << log;

  const CommandResult rigid = run_vulnus(short_paper_run + exact + "--output rigid", scratch.path);
  ASSERT_EQ(rigid.exit_status, 0) << rigid.out << rigid.err;
  EXPECT_FALSE(mentions(warnings_of(scratch.path / "rigid"), "Contact/Rigid surface = exact"));
}

// A fixed face 4 mm (two cells) beyond the slab holds nothing: a face condition acts on the
// face's grid nodes, which the slab's points do not reach. It was listed as 'fixed' with a zero
// impulse; `vulnus check` and the run now warn, and summary.json's supports say so. The faces
// on the slab stay plain 'fixed'.
TEST(SceneWarnings, ASupportNoBodyReachesIsFlagged)
{
  ScratchDirectory scratch("scene_warning_unreached_face");
  const std::string beyond = short_paper_run + "--set 'Grid/Domain min=-0.029, -0.02, -0.025' ";
  const std::string warning =
    "Grid/Boundary conditions/x- = fixed: no deformable body reaches that face (the nearest, "
    "'slab', is 4 mm from it";
  const CommandResult check = run_vulnus("check " + beyond.substr(4), scratch.path); // no "run"
  ASSERT_EQ(check.exit_status, 0) << check.out << check.err;
  EXPECT_NE(check.err.find("vulnus: warning: " + warning), std::string::npos) << check.err;
  EXPECT_EQ(check.err.find("Boundary conditions/x+"), std::string::npos) << check.err;

  const CommandResult run = run_vulnus(beyond + "--output run", scratch.path);
  ASSERT_EQ(run.exit_status, 0) << run.out << run.err;
  EXPECT_TRUE(mentions(warnings_of(scratch.path / "run"), warning));
  const nlohmann::json summary =
    nlohmann::json::parse(read_text(scratch.path / "run" / "summary.json"));
  EXPECT_EQ(summary["supports"]["x-"]["condition"], "fixed (no body reached it)");
  EXPECT_EQ(summary["supports"]["x+"]["condition"], "fixed");
  EXPECT_EQ(summary["supports"]["y-"]["condition"], "free");
}
