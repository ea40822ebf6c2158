// The late mean and range of a ringing record (analysis/late_window.h) against closed forms,
// and history.csv's columns read back (io/csv_columns.h).
#include "analysis/late_window.h"
#include "io/csv_columns.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace
{
using vulnus::analysis::late_window;

/// A linear record has the mean of its ends over any window, which the trapezoid rule takes
/// exactly, also when the window's start falls inside a sample interval.
TEST(LateWindow, LinearRecordHasTheMeanOfItsEndsOverTheSecondHalf)
{
  const std::vector<double> t{0.0, 0.3, 1.1, 1.7, 2.0};
  std::vector<double> v;
  for (const double x : t)
    v.push_back(5.0 - 2.0 * x);
  const auto w = late_window(t, v);
  EXPECT_DOUBLE_EQ(w.from_time, 1.0);
  EXPECT_DOUBLE_EQ(w.to_time, 2.0);
  EXPECT_NEAR(w.mean, 5.0 - 2.0 * 1.5, 1e-14);
  EXPECT_NEAR(w.min, 1.0, 1e-14);
  EXPECT_NEAR(w.max, 3.0, 1e-14); // the interpolated value at the window's start
}

/// An impulse ringing about its mean I0 with amplitude A: the end value moves by up to 2A
/// with the ring's phase, the late mean by at most A / (pi n) over n periods (here 5.5 periods
/// in the window: below 0.06 A), and the range is the ring's.
TEST(LateWindow, MeanOfARingDoesNotDependOnItsPhase)
{
  const double I0 = -2e-4, A = 2.5e-4, period = 14e-6, end = 154e-6;
  for (const double phase : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0})
  {
    std::vector<double> t, v;
    for (int i = 0; i <= 2000; ++i)
    {
      t.push_back(end * i / 2000);
      v.push_back(I0 + A * std::sin(2.0 * M_PI * t.back() / period + phase));
    }
    const auto w = late_window(t, v);
    EXPECT_NEAR(w.mean, I0, 0.06 * A) << phase;
    EXPECT_NEAR(w.min, I0 - A, 1e-3 * A) << phase;
    EXPECT_NEAR(w.max, I0 + A, 1e-3 * A) << phase;
  }
}

TEST(LateWindow, RefusesTooFewSamplesOrNoTimeSpan)
{
  EXPECT_THROW(late_window({1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(late_window({1.0, 1.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(late_window({0.0, 1.0}, {1.0}), std::invalid_argument);
}

TEST(CsvColumns, ReadsNamedColumnsAndNamesWhatIsWrong)
{
  const std::filesystem::path path =
    std::filesystem::temp_directory_path() / "vulnus_csv_columns_test.csv";
  {
    std::ofstream out(path);
    out << "time_s,a,support_impulse_x+\n0,1,-1e-05\n1e-06,2,nan\n2e-06,3,4.5\n";
  }
  const auto columns = vulnus::io::read_csv_columns(path.string(), {"support_impulse_x+", "time_s"});
  ASSERT_EQ(columns.size(), 2u);
  ASSERT_EQ(columns[0].size(), 3u);
  EXPECT_DOUBLE_EQ(columns[0][0], -1e-5);
  EXPECT_TRUE(std::isnan(columns[0][1]));
  EXPECT_DOUBLE_EQ(columns[0][2], 4.5);
  EXPECT_DOUBLE_EQ(columns[1][2], 2e-6);
  try
  {
    vulnus::io::read_csv_columns(path.string(), {"missing"});
    ADD_FAILURE() << "a missing column was accepted";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("\"missing\""), std::string::npos) << e.what();
  }
  {
    std::ofstream out(path, std::ios::app);
    out << "3e-06,x4,5\n";
  }
  try
  {
    vulnus::io::read_csv_columns(path.string(), {"a"});
    ADD_FAILURE() << "a field that is not a number was accepted";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("line 5"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}
} // namespace
