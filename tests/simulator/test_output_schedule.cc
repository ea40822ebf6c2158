// The periodic output schedule, and how it resumes from a checkpoint.
#include "simulator/output_schedule.h"

#include <gtest/gtest.h>

using vulnus::simulator::OutputSchedule;

TEST(OutputSchedule, WritesEveryIntervalAndResumesWhereTheCheckpointLeftIt)
{
  OutputSchedule schedule(1e-5);
  EXPECT_FALSE(schedule.due(0.9e-5));
  EXPECT_TRUE(schedule.due(1e-5));
  schedule.advance();
  EXPECT_FALSE(schedule.due(1.5e-5));
  EXPECT_TRUE(schedule.due(2e-5));
  OutputSchedule resumed(1e-5);
  resumed.resume(schedule.next_time(), 1.5e-5);
  EXPECT_FALSE(resumed.due(1.9e-5));
  EXPECT_TRUE(resumed.due(2e-5));
}

TEST(OutputSchedule, WithoutAnIntervalNothingPeriodicIsDueEvenAfterARestart)
{
  // A checkpoint of an earlier build saved twice its run's end time (9e-4 s for an end of
  // 4.5e-4 s); a restart to a later end time passed it and then wrote at every step.
  OutputSchedule schedule(0.0);
  EXPECT_FALSE(schedule.due(1.0));
  schedule.resume(9e-4, 4.4e-4);
  for (const double t : {8e-4, 9e-4, 1e-3, 5e-3})
    EXPECT_FALSE(schedule.due(t)) << t;
}

TEST(OutputSchedule, ARestartWithANewIntervalWritesOnTheNewOne)
{
  // From a run without periodic output (next: never) ...
  OutputSchedule from_none(1e-5);
  from_none.resume(std::numeric_limits<double>::infinity(), 3.3e-5);
  EXPECT_FALSE(from_none.due(3.9e-5));
  EXPECT_TRUE(from_none.due(4e-5));
  // ... and from one whose interval was ten times longer (next at 1e-4).
  OutputSchedule from_longer(1e-5);
  from_longer.resume(1e-4, 3.3e-5);
  EXPECT_TRUE(from_longer.due(4e-5));
}
