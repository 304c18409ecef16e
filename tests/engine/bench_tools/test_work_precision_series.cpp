// The CSV grouping behind bench/tools/work_precision_plot: one series per (variant, method), points sorted
// by cost, failed rows left out with their reason. Inputs are small CSV texts in the bench's layout.
#include <gtest/gtest.h>

#include <stdexcept>

#include "work_precision_series.hpp"

namespace maris::bench {
namespace {

// Rows in run order as the bench writes them: the implicit steps T/25 … T/200 are not in cost order
// (Newton needs more iterations at the long step), and one RK4 run failed.
const char* kCsv =
    "case,variant,n,method,setting,cpu_time,error_same_n,note\n"
    "-,-,-,-,s or -,s,-,-\n"
    "case5,A2,100,rk4,0.012,0.69,3.8e-08,\n"
    "case5,A2,100,rk4,0.006,1.40,6.2e-09,\n"
    "case5,A2,100,implicit,0.4,1.20,2.0e-02,\n"
    "case5,A2,100,implicit,0.2,0.57,6.6e-03,\n"
    "case5,A2,100,implicit,0.1,0.42,2.1e-03,\n"
    "case5,A2,100,rk4,0.024,0,inf,solver failed at t = 1.25 s (step 3): state component 9 has a non-finite time derivative\n"
    "case5,J3,100,rk4,0.002,4.1,3.7e-07,\n"
    "case5,J3,50,rk4,0.004,1.1,2.6e-03,\n";

SeriesSelection caseFiveAtHundred() {
  SeriesSelection s;
  s.x = "cpu_time";
  s.y = "error_same_n";
  s.series_columns = {"variant", "method"};
  s.where = {{"case", "case5"}, {"n", "100"}};
  s.detail_columns = {"setting"};
  s.note_column = "note";
  return s;
}

TEST(WorkPrecisionSeries, OneSeriesPerVariantAndMethodInOrderOfAppearance) {
  const WorkPrecisionSet set = groupWorkPrecision(parseTextCsv(kCsv), caseFiveAtHundred());
  ASSERT_EQ(set.series.size(), 3u);
  EXPECT_EQ(set.series[0].label, "A2 rk4");
  EXPECT_EQ(set.series[1].label, "A2 implicit");
  EXPECT_EQ(set.series[2].label, "J3 rk4");
  EXPECT_EQ(set.series[0].points.size(), 2u);
  EXPECT_EQ(set.series[2].points.size(), 1u);  // the n = 50 row is filtered out
  EXPECT_EQ(set.x_unit, "s");
  EXPECT_EQ(set.y_unit, "-");
}

TEST(WorkPrecisionSeries, PointsAreSortedByCostNotByRunOrder) {
  const WorkPrecisionSet set = groupWorkPrecision(parseTextCsv(kCsv), caseFiveAtHundred());
  const auto& implicit = set.series[1].points;
  ASSERT_EQ(implicit.size(), 3u);
  EXPECT_DOUBLE_EQ(implicit[0].first, 0.42);
  EXPECT_DOUBLE_EQ(implicit[0].second, 2.1e-3);
  EXPECT_DOUBLE_EQ(implicit[1].first, 0.57);
  EXPECT_DOUBLE_EQ(implicit[2].first, 1.20);
  EXPECT_DOUBLE_EQ(implicit[2].second, 2.0e-2);
}

TEST(WorkPrecisionSeries, FailedRowsAreLeftOutWithTheirReason) {
  const WorkPrecisionSet set = groupWorkPrecision(parseTextCsv(kCsv), caseFiveAtHundred());
  ASSERT_EQ(set.left_out.size(), 1u);
  EXPECT_EQ(set.left_out[0], "A2 rk4 setting 0.024: solver failed at t = 1.25 s (step 3): state component 9");
  const std::string note = leftOutNote(set.left_out, 6);
  EXPECT_NE(note.find("1 row left out"), std::string::npos) << note;
  EXPECT_EQ(leftOutNote({}, 6), "");
}

TEST(WorkPrecisionSeries, WithoutANoteColumnTheValueIsShown) {
  SeriesSelection s = caseFiveAtHundred();
  s.note_column = "reason";  // not in the CSV: the failed row is described by its values
  const WorkPrecisionSet set = groupWorkPrecision(parseTextCsv(kCsv), s);
  ASSERT_EQ(set.left_out.size(), 1u);
  EXPECT_EQ(set.left_out[0], "A2 rk4 setting 0.024: error_same_n = inf, cpu_time = 0");
}

TEST(WorkPrecisionSeries, BadInputNamesTheProblem) {
  SeriesSelection s = caseFiveAtHundred();
  s.y = "error_finest_n";
  try {
    groupWorkPrecision(parseTextCsv(kCsv), s);
    FAIL() << "no error for a missing column";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("error_finest_n"), std::string::npos) << e.what();
  }
  try {
    parseTextCsv("a,b\n-,-\n1,2\n3\n");
    FAIL() << "no error for a short row";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseTextCsv("a,b\n"), std::runtime_error);
}

}  // namespace
}  // namespace maris::bench
