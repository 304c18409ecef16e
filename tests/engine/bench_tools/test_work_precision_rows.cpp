// The merge behind MARIS_BENCH_NLIST (bench/riser_work_precision.cpp): a run of chosen n replaces the rows of
// the same key in the committed CSV and keeps the others, in case/variant/n order; older CSVs without the
// finest_n and reference columns still read. Inputs are small CSV texts in the bench's layout.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "work_precision_rows.hpp"

namespace maris::bench {
namespace {

// An older file (no finest_n, no reference column) with a duplicated row, as a hand-concatenated run left it.
const char* kOldCsv =
    "case,variant,n,method,setting,steps,rhs_evaluations,cpu_time,error_same_n,error_finest_n,note\n"
    "-,-,-,-,s or -,-,-,s,-,-,-\n"
    "case5,J3,200,rk4,9.892e-04,36393,145573,1.6063e+01,3.109e-07,3.109e-07,\n"
    "case5,J3,200,implicit,5.000e-02,720,2264,8.5825e-01,1.070e-03,1.070e-03,\n"
    "cable3d,A3,50,implicit,2.000e-02,500,1723,2.8360e-01,2.008e-04,2.008e-04,\n"
    "cable3d,A3,50,implicit,2.000e-02,500,1723,2.8360e-01,2.008e-04,2.008e-04,\n"
    "case5,A2,10,rk4,4.170e-01,0,0,0,inf,inf,solver failed at t = 1.25 s (step 3): drag\n";

WorkPrecisionRow row(const char* case_name, const char* variant, int n, const char* method, double setting,
                     double cpu) {
  WorkPrecisionRow r;
  r.case_name = case_name, r.variant = variant, r.n = n, r.method = method, r.setting = setting, r.cpu = cpu;
  r.steps = 10, r.error_same_n = 1e-3, r.error_finest_n = 2e-3, r.finest_n = 400, r.reference = "rk4 0.45x limit";
  return r;
}

TEST(WorkPrecisionRows, OlderCsvReadsWithEmptyNewColumns) {
  const auto rows = parseWorkPrecisionRows(kOldCsv);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].variant, "J3");
  EXPECT_EQ(rows[0].n, 200);
  EXPECT_DOUBLE_EQ(rows[0].cpu, 16.063);
  EXPECT_EQ(rows[0].finest_n, 0);
  EXPECT_EQ(rows[0].reference, "");
  EXPECT_TRUE(std::isinf(rows[4].error_same_n));
  EXPECT_EQ(rows[4].note, "solver failed at t = 1.25 s (step 3): drag");
}

TEST(WorkPrecisionRows, MergeReplacesRowsOfTheSameKeyAndKeepsTheRest) {
  const auto old_rows = parseWorkPrecisionRows(kOldCsv);
  // The same J3 n = 200 implicit setting (printed equal at %.3e) plus new n = 400 rows, in run order.
  const std::vector<WorkPrecisionRow> new_rows = {row("case5", "J3", 400, "rk4", 4.946e-4, 68.0),
                                                  row("case5", "J3", 200, "implicit", 0.05000000001, 0.9),
                                                  row("case5", "J2", 400, "implicit", 0.05, 2.0)};
  const auto merged = mergeWorkPrecisionRows(old_rows, new_rows);
  // 5 old - 1 duplicate - 1 replaced + 3 new.
  ASSERT_EQ(merged.size(), 6u);
  // Order: case5 before cable3d; J2 before J3 before A2; n ascending within a variant.
  EXPECT_EQ(workPrecisionKey(merged[0]), "case5|J2|400|implicit|5.000e-02");
  EXPECT_EQ(workPrecisionKey(merged[1]), "case5|J3|200|rk4|9.892e-04");
  EXPECT_EQ(workPrecisionKey(merged[2]), "case5|J3|200|implicit|5.000e-02");
  EXPECT_DOUBLE_EQ(merged[2].cpu, 0.9);  // the new row, not the old 0.858
  EXPECT_EQ(workPrecisionKey(merged[3]), "case5|J3|400|rk4|4.946e-04");
  EXPECT_EQ(merged[4].variant, "A2");
  EXPECT_EQ(merged[5].case_name, "cable3d");
}

TEST(WorkPrecisionRows, WrittenRowsReadBackWithTextCellsKeptOnOneLine) {
  WorkPrecisionRow r = row("cable3d", "J3", 400, "dopri5", 1e-3, 0.0);
  r.error_same_n = r.error_finest_n = INFINITY;
  r.note = "skipped: estimated 229 s CPU, 65536 steps\nx";
  const auto back = parseWorkPrecisionRows(workPrecisionHeader() + workPrecisionLine(r));
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].note, "skipped: estimated 229 s CPU; 65536 steps x");
  EXPECT_EQ(back[0].finest_n, 400);
  EXPECT_EQ(back[0].reference, "rk4 0.45x limit");
  EXPECT_TRUE(std::isinf(back[0].error_same_n));
}

TEST(WorkPrecisionRows, MalformedCsvIsRejected) {
  EXPECT_THROW(parseWorkPrecisionRows("case,variant\n-,-\n"), std::runtime_error);  // required columns missing
}

}  // namespace
}  // namespace maris::bench
