#include "work_precision_rows.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "work_precision_series.hpp"

namespace maris::bench {
namespace {

std::string cell(std::string text) {
  for (char& c : text)
    if (c == ',') c = ';';
    else if (c == '\n' || c == '\r') c = ' ';
  return text;
}

int rankOf(const std::string& value, std::initializer_list<const char*> order) {
  int rank = 0;
  for (const char* name : order) {
    if (value == name) return rank;
    ++rank;
  }
  return rank;
}

}  // namespace

std::string formatNumber(const char* spec, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, spec, value);
  return buffer;
}

std::string workPrecisionHeader() {
  return "case,variant,n,method,setting,steps,rhs_evaluations,cpu_time,error_same_n,error_finest_n,finest_n,"
         "reference,note\n-,-,-,-,s or -,-,-,s,-,-,-,-,-\n";
}

std::string workPrecisionLine(const WorkPrecisionRow& r) {
  return cell(r.case_name) + "," + cell(r.variant) + "," + std::to_string(r.n) + "," + cell(r.method) + "," +
         formatNumber("%.3e", r.setting) + "," + std::to_string(r.steps) + "," + std::to_string(r.rhs_evaluations) +
         "," + formatNumber("%.4e", r.cpu) + "," + formatNumber("%.3e", r.error_same_n) + "," +
         formatNumber("%.3e", r.error_finest_n) + "," + std::to_string(r.finest_n) + "," + cell(r.reference) + "," +
         cell(r.note) + "\n";
}

std::vector<WorkPrecisionRow> parseWorkPrecisionRows(const std::string& csv_text) {
  const TextTable table = parseTextCsv(csv_text);
  auto column = [&](const char* name) -> long {
    const auto it = std::find(table.names.begin(), table.names.end(), name);
    return it == table.names.end() ? -1 : static_cast<long>(it - table.names.begin());
  };
  for (const char* required : {"case", "variant", "n", "method", "setting", "steps", "rhs_evaluations", "cpu_time",
                               "error_same_n", "error_finest_n"})
    if (column(required) < 0) throw std::runtime_error(std::string("no column '") + required + "' in the CSV");
  std::vector<WorkPrecisionRow> rows;
  for (const auto& cells : table.rows) {
    auto text = [&](const char* name) { return column(name) < 0 ? std::string() : cells[column(name)]; };
    auto number = [&](const char* name) { return std::strtod(text(name).c_str(), nullptr); };
    WorkPrecisionRow r;
    r.case_name = text("case");
    r.variant = text("variant");
    r.method = text("method");
    r.n = std::atoi(text("n").c_str());
    r.setting = number("setting");
    r.steps = std::atol(text("steps").c_str());
    r.rhs_evaluations = std::atol(text("rhs_evaluations").c_str());
    r.cpu = number("cpu_time");
    r.error_same_n = number("error_same_n");
    r.error_finest_n = number("error_finest_n");
    r.finest_n = std::atoi(text("finest_n").c_str());
    r.reference = text("reference");
    r.note = text("note");
    rows.push_back(r);
  }
  return rows;
}

std::string workPrecisionKey(const WorkPrecisionRow& r) {
  return r.case_name + "|" + r.variant + "|" + std::to_string(r.n) + "|" + r.method + "|" +
         formatNumber("%.3e", r.setting);
}

std::vector<WorkPrecisionRow> mergeWorkPrecisionRows(const std::vector<WorkPrecisionRow>& old_rows,
                                                     const std::vector<WorkPrecisionRow>& new_rows) {
  std::map<std::string, bool> replaced;
  for (const auto& r : new_rows) replaced[workPrecisionKey(r)] = true;
  // Last occurrence wins among old duplicates: keep an old row only if no later old row has its key.
  std::map<std::string, std::size_t> last_old;
  for (std::size_t k = 0; k < old_rows.size(); ++k) last_old[workPrecisionKey(old_rows[k])] = k;
  std::vector<WorkPrecisionRow> merged;
  for (std::size_t k = 0; k < old_rows.size(); ++k) {
    const std::string key = workPrecisionKey(old_rows[k]);
    if (!replaced.count(key) && last_old[key] == k) merged.push_back(old_rows[k]);
  }
  merged.insert(merged.end(), new_rows.begin(), new_rows.end());
  std::stable_sort(merged.begin(), merged.end(), [](const WorkPrecisionRow& a, const WorkPrecisionRow& b) {
    const int ca = rankOf(a.case_name, {"rhs_cost", "case5", "cable3d"});
    const int cb = rankOf(b.case_name, {"rhs_cost", "case5", "cable3d"});
    if (ca != cb) return ca < cb;
    const int va = rankOf(a.variant, {"J2", "J3", "A2", "A3"}), vb = rankOf(b.variant, {"J2", "J3", "A2", "A3"});
    if (va != vb) return va < vb;
    return a.n < b.n;
  });
  return merged;
}

}  // namespace maris::bench
