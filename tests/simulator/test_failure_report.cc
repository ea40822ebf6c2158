// describe_failure: a blow-up keeps its message, with the solver's parameter names spelled as
// the deck spells them and its own remedy apart; a deal.II exception is cut to its "Additional
// information" (no source locations, no stack trace); anything else keeps what().
#include "simulator/failure_report.h"

#include "deck/scene_entries.h"
#include "mpm/solver.h"

#include <deal.II/base/exceptions.h>

#include <gtest/gtest.h>

namespace
{
std::string bare(const std::string& name) { return name; }

vulnus::simulator::FailureReport describe_failure(const std::exception& e)
{
  return vulnus::simulator::describe_failure(e, bare);
}

TEST(FailureReport, KeepsABlowUpMessage)
{
  const auto r = describe_failure(vulnus::mpm::BlowUp("point 7 inverted"));
  EXPECT_EQ(r.kind, "blow-up");
  EXPECT_EQ(r.message, "point 7 inverted");
  EXPECT_EQ(r.remedy, "");
}

TEST(FailureReport, SpellsABlowUpsParametersAsTheDeckDoes)
{
  const vulnus::BlowUp e(vulnus::RunFailure{"CFL step 1e-9 s is below {min_time_step} 1e-8 s",
                                            "a point moving far too fast",
                                            "a smaller {cfl}, or free {domain_faces.x+}"});
  // Uncaught, what() names the solver's own parameters.
  EXPECT_EQ(std::string(e.what()), "CFL step 1e-9 s is below min_time_step 1e-8 s; likely cause: "
                                   "a point moving far too fast; remedy: a smaller cfl, or free "
                                   "domain_faces.x+");
  const auto r = vulnus::simulator::describe_failure(e, vulnus::deck::entry_of_scene_parameter);
  EXPECT_EQ(r.message, "CFL step 1e-9 s is below Time/Minimum time step 1e-8 s; likely cause: a "
                       "point moving far too fast");
  EXPECT_EQ(r.remedy, "a smaller Time/CFL, or free Grid/Boundary conditions/x+");
}

TEST(FailureReport, LeavesTextWithoutParametersAndUnknownNamesAlone)
{
  const auto spell = vulnus::deck::entry_of_scene_parameter;
  EXPECT_EQ(vulnus::with_spelled_parameters("no names here", spell), "no names here");
  EXPECT_EQ(vulnus::with_spelled_parameters("{not_a_parameter} and {cell_size}", spell),
            "not_a_parameter and Grid/Cell size");
  EXPECT_EQ(vulnus::with_spelled_parameters("an open { brace", spell), "an open { brace");
}

TEST(FailureReport, CutsADealIIExceptionToItsAdditionalInformation)
{
  try
  {
    AssertThrow(1 + 1 == 3, dealii::ExcMessage("the Krylov solver broke down at iteration 12"));
    FAIL() << "AssertThrow did not throw";
  }
  catch (const std::exception& e)
  {
    ASSERT_NE(std::string(e.what()).find("An error occurred"), std::string::npos) << e.what();
    const auto r = describe_failure(e);
    EXPECT_EQ(r.kind, "FE solver failure");
    EXPECT_EQ(r.message, "the Krylov solver broke down at iteration 12");
  }
}

TEST(FailureReport, ALinearSolverBreakdownNamesTheImplicitFarFieldsRemedies)
{
  // Trilinos's AztecOO, as the implicit far field with F-bar met it in a long window.
  try
  {
    AssertThrow(false, dealii::ExcMessage("AztecOO::Iterate error code -3: numerical breakdown"));
  }
  catch (const std::exception& e)
  {
    const auto r = describe_failure(e);
    EXPECT_EQ(r.kind, "FE solver failure");
    EXPECT_NE(r.remedy.find("Hybrid/Substeps"), std::string::npos) << r.remedy;
    EXPECT_NE(r.remedy.find("Far field/Volume averaging"), std::string::npos) << r.remedy;
    EXPECT_NE(r.remedy.find("central difference"), std::string::npos) << r.remedy;
  }
  // Not a linear solve: the stepper's own remedy applies.
  try
  {
    AssertThrow(false, dealii::ExcMessage("an inverted element"));
  }
  catch (const std::exception& e)
  {
    EXPECT_EQ(describe_failure(e).remedy, "");
  }
}

TEST(FailureReport, CutsAnyDealIIExceptionToOneParagraph)
{
  try
  {
    AssertThrow(2 < 1, dealii::ExcInternalError());
    FAIL() << "AssertThrow did not throw";
  }
  catch (const std::exception& e)
  {
    const auto r = describe_failure(e);
    EXPECT_EQ(r.kind, "FE solver failure");
    EXPECT_FALSE(r.message.empty());
    EXPECT_EQ(r.message.find('\n'), std::string::npos) << r.message;
    EXPECT_EQ(r.message.find("An error occurred"), std::string::npos) << r.message;
    EXPECT_EQ(r.message.find("Stacktrace"), std::string::npos) << r.message;
  }
}

TEST(FailureReport, KeepsAnyOtherErrorMessage)
{
  const auto r = describe_failure(std::runtime_error("element 4 inverted"));
  EXPECT_EQ(r.kind, "breakdown");
  EXPECT_EQ(r.message, "element 4 inverted");
}
} // namespace
