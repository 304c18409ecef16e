// Rows of the riser work–precision CSV (bench/riser_work_precision.cpp) and their merge: a run of chosen n
// (MARIS_BENCH_NLIST) replaces the rows of the same key in the committed CSV and keeps the others, so the
// tables and plots are always drawn from the whole CSV. Plain C++ (no engine, no Qt): tested in
// test_engine_bench_tools.
#pragma once

#include <string>
#include <vector>

namespace maris::bench {

// One row: a run (or a skipped or failed one) of one case, variant, n, method and setting.
struct WorkPrecisionRow {
  std::string case_name, variant, method;
  int n = 0;
  double setting = 0;  // [s] step, or rtol (dopri5)
  long steps = 0, rhs_evaluations = 0;
  double cpu = 0;  // [s] thread CPU time of the integration
  double error_same_n = 0, error_finest_n = 0;  // inf for a failed or skipped run
  int finest_n = 0;       // n of the finest-n reference the row's error_finest_n is measured against (0: none)
  std::string reference;  // how the same-n reference was integrated ("dopri5 1e-10", "rk4 0.2x", ...)
  std::string note;       // why the run failed or was skipped ("" if it ran)
};

// `value` printed with one printf conversion (`spec`, e.g. "%.3e"): the CSV cells and the markdown tables.
std::string formatNumber(const char* spec, double value);

// The CSV header (names row and units row, each ending in a newline).
std::string workPrecisionHeader();

// One data row (commas and line breaks in text cells become semicolons and spaces).
std::string workPrecisionLine(const WorkPrecisionRow& row);

// Rows of a CSV written by workPrecisionHeader/Line. Columns added later (finest_n, reference) may be
// missing in older files: their cells stay 0 / "". Throws std::runtime_error on a malformed file.
std::vector<WorkPrecisionRow> parseWorkPrecisionRows(const std::string& csv_text);

// Key of a row: case, variant, n, method and the setting as the CSV prints it (%.3e).
std::string workPrecisionKey(const WorkPrecisionRow& row);

// `old_rows` with every row whose key occurs in `new_rows` replaced, plus the new rows, ordered by case
// (rhs_cost, case5, cable3d, others), variant (J2, J3, A2, A3) and n; rows of equal rank keep their order
// (old before new). Duplicate keys within old_rows collapse to the last one.
std::vector<WorkPrecisionRow> mergeWorkPrecisionRows(const std::vector<WorkPrecisionRow>& old_rows,
                                                     const std::vector<WorkPrecisionRow>& new_rows);

}  // namespace maris::bench
