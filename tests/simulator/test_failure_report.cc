// describe_failure: a blow-up keeps its message; a deal.II exception is cut to its
// "Additional information" (no source locations, no stack trace); anything else keeps what().
#include "simulator/failure_report.h"

#include "mpm/solver.h"

#include <deal.II/base/exceptions.h>

#include <gtest/gtest.h>

namespace
{
using vulnus::simulator::describe_failure;

TEST(FailureReport, KeepsABlowUpMessage)
{
  const auto r = describe_failure(vulnus::mpm::BlowUp("point 7 inverted"));
  EXPECT_EQ(r.kind, "blow-up");
  EXPECT_EQ(r.message, "point 7 inverted");
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
