// Markdown tables of the riser work–precision rows (bench/riser_work_precision.cpp writes them beside the
// CSV, always from the whole merged CSV): right-hand-side cost against n, case 5 at n = 100, RK4 and the
// implicit integrator against n, and the rows that were skipped (estimated cost above the budget) or failed.
#pragma once

#include <string>
#include <vector>

#include "work_precision_rows.hpp"

namespace maris::bench {

// `run_note` heads the tables: which rows the last run produced, its load averages, where earlier runs are logged.
std::string riserWorkPrecisionSummary(const std::vector<WorkPrecisionRow>& rows, const std::string& run_note);

}  // namespace maris::bench
