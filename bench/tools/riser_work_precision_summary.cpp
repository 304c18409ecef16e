#include "riser_work_precision_summary.hpp"

#include <cmath>
#include <map>
#include <sstream>

namespace maris::bench {
namespace {

bool ran(const WorkPrecisionRow& r) { return r.note.empty() && r.steps > 0; }

std::string finest(const WorkPrecisionRow& r) {
  const std::string n = r.finest_n > 0 ? " (n = " + std::to_string(r.finest_n) + ")" : "";
  return formatNumber("%.2e", r.error_finest_n) + n;
}

}  // namespace

std::string riserWorkPrecisionSummary(const std::vector<WorkPrecisionRow>& rows, const std::string& run_note) {
  std::ostringstream md;
  md << "Written by `scripts/bench_riser.sh` (bench_riser_work_precision; do not edit by hand) from the whole\n"
     << "`riser_work_precision.csv`: runs of chosen n (`MARIS_BENCH_NLIST`, `MARIS_BENCH_CABLE_NLIST`) replace the rows\n"
     << "of the same key and keep the rest; each run's settings and load average are in `riser_work_precision.log`.\n"
     << run_note << "\n\n"
     << "CPU = thread CPU seconds of the integration only; error = max |r(L/2) − r_ref(L/2)| / max motion, against the\n"
     << "same-n reference (column `reference` of the CSV); \"finest n\" errors are against the J3 reference at the\n"
     << "finest n of the run that produced the row (named in brackets).\n\n";
  md << "**Cost of one right-hand side** [µs] (per segment in brackets); linear growth means a constant bracket:\n\n"
     << "| variant | n = 10 | 20 | 50 | 100 | 200 | 400 | 1000 |\n|---|---|---|---|---|---|---|---|\n";
  for (const char* v : {"J2", "J3", "A2", "A3"}) {
    md << "| " << v;
    for (const auto& r : rows)
      if (r.case_name == "rhs_cost" && r.variant == v)
        md << " | " << formatNumber("%.1f", 1e6 * r.cpu) << " (" << formatNumber("%.2f", 1e6 * r.cpu / r.n) << ")";
    md << " |\n";
  }
  md << "\n**Case 5, n = 100, 36 s simulated:**\n\n"
     << "| variant | method | step [s] or rtol | steps | CPU [s] | error (same n) | error (finest n) |\n"
     << "|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    if (r.case_name != "case5" || r.n != 100) continue;
    md << "| " << r.variant << " | " << r.method << " | " << formatNumber("%.3g", r.setting) << " | ";
    if (!ran(r))
      md << (r.note.rfind("skipped", 0) == 0 ? "" : "failed: ") << r.note << " | | | |\n";
    else
      md << r.steps << " | " << formatNumber("%.3f", r.cpu) << " | " << formatNumber("%.2e", r.error_same_n) << " | "
         << finest(r) << " |\n";
  }
  md << "\n**RK4 against n** (first RK4 row that ran: 0.9 × the stability estimate, else 0.45 ×):\n\n"
     << "| case | variant | n | step [s] | steps | CPU [s] | CPU/(steps·n) [µs] | error (same n) | error (finest n) |\n"
     << "|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, bool> seen;
  for (const auto& r : rows) {
    const std::string key = r.case_name + r.variant + std::to_string(r.n);
    if (r.method != "rk4" || r.case_name == "rhs_cost" || seen[key] || !ran(r)) continue;
    seen[key] = true;
    md << "| " << r.case_name << " | " << r.variant << " | " << r.n << " | " << formatNumber("%.3g", r.setting)
       << " | " << r.steps << " | " << formatNumber("%.3f", r.cpu) << " | "
       << formatNumber("%.3f", 1e6 * r.cpu / (double(r.steps) * r.n)) << " | "
       << formatNumber("%.2e", r.error_same_n) << " | " << finest(r) << " |\n";
  }
  md << "\n**Implicit generalized-α at T/200 against n** (case 5: 50 ms, cable: 20 ms; T = top-motion period):\n\n"
     << "| case | variant | n | steps | CPU [s] | error (same n) | error (finest n) | same-n reference |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const bool t200 = (r.case_name == "case5" && std::abs(r.setting - 0.05) < 1e-9) ||
                      (r.case_name == "cable3d" && std::abs(r.setting - 0.02) < 1e-9);
    if (r.method != "implicit" || !t200 || !ran(r)) continue;
    md << "| " << r.case_name << " | " << r.variant << " | " << r.n << " | " << r.steps << " | "
       << formatNumber("%.3f", r.cpu) << " | " << formatNumber("%.2e", r.error_same_n) << " | " << finest(r) << " | "
       << r.reference << " |\n";
  }
  md << "\n**Rows that did not run** (skipped: estimated CPU above the run's budget; failed: the solver's message):\n\n";
  bool any = false;
  for (const auto& r : rows) {
    if (ran(r) || r.case_name == "rhs_cost") continue;
    any = true;
    md << "- " << r.case_name << " " << r.variant << " n = " << r.n << " " << r.method << " "
       << formatNumber("%.3g", r.setting) << ": " << (r.note.empty() ? std::string("no same-n reference") : r.note) << "\n";
  }
  if (!any) md << "none\n";
  return md.str();
}

}  // namespace maris::bench
