#include "plots/plot_export.hpp"

#include <map>
#include <cstdio>
#include <stdexcept>

#include "core/run_folder.hpp"
#include "core/run_output.hpp"
#include "plots/result_plot.hpp"

namespace maris::ui {

Table plotDataTable(const Results& results, const PlotSpec& spec) {
  Table out;
  out.name = spec.name;
  out.title = spec.title;
  const Table* table = results.findTable(spec.table);
  if (!table) return out;
  const Column* x = table->find(spec.x);
  if (!x) return out;
  out.columns.push_back(*x);
  for (const auto& name : spec.y)
    if (const Column* y = table->find(name)) out.columns.push_back(*y);
  return out;
}

void writePlotCsv(const std::filesystem::path& file, const Results& results, const PlotSpec& spec) {
  const Table table = plotDataTable(results, spec);
  if (table.columns.empty())
    throw std::runtime_error("plot '" + spec.name + "' has no data table '" + spec.table + "' in these results");
  writeFileAtomic(file, table.toCsv());
}

Table plotDataOfRuns(const std::vector<RunData>& runs, const PlotSpec& spec) {
  Table out;
  out.name = spec.name + "_runs";
  out.title = spec.title;
  for (const auto& run : runs) {
    if (!run.results) continue;
    const Table one = plotDataTable(*run.results, spec);
    if (one.columns.size() != spec.y.size() + 1) continue;  // this run lacks a column of the plot
    if (out.columns.empty()) {
      out.add("run", "-");
      for (const auto& c : one.columns) out.add(c.name, c.unit);
    }
    out.columns[0].values.insert(out.columns[0].values.end(), one.rows(), static_cast<double>(run.id));
    for (std::size_t c = 0; c < one.columns.size(); ++c)
      out.columns[c + 1].values.insert(out.columns[c + 1].values.end(), one.columns[c].values.begin(),
                                       one.columns[c].values.end());
  }
  return out;
}

void writeRunsCsv(const std::filesystem::path& file, const std::vector<RunData>& runs, const PlotSpec& spec) {
  const Table table = plotDataOfRuns(runs, spec);
  if (table.columns.empty()) throw std::runtime_error("no run has the data of plot '" + spec.name + "'");
  std::map<unsigned long long, std::string> scenario_of;
  for (const auto& r : runs) scenario_of[r.id] = r.scenario;
  // The numeric table with a text column spliced in after "run": names row, units row, then each data row by
  // its run number.
  const std::string numeric = table.toCsv();
  std::string csv;
  std::size_t start = 0;
  for (int line = 0; start < numeric.size(); ++line) {
    const std::size_t end = numeric.find('\n', start);
    const std::string row = numeric.substr(start, end - start);
    const std::size_t comma = row.find(',');
    const std::string first = row.substr(0, comma);
    std::string cell = line == 0 ? "scenario" : line == 1 ? "-" : scenario_of[std::stoull(first)];
    std::string quoted = "\"";
    for (char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    quoted += '"';
    csv += first + "," + quoted + (comma == std::string::npos ? "" : row.substr(comma)) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  writeFileAtomic(file, csv);
}

namespace {

std::string formatNumber(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

}  // namespace

std::string markdownTableCell(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '|' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\r' || c == '\n') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      out += "<br>";
    } else {
      out += c;
    }
  }
  return out;
}

std::string summaryMarkdown(const Scenario& scenario, const Results& results,
                            const std::vector<std::filesystem::path>& files) {
  std::string md = "# " + scenario.name + "\n\nScene: `" + scenario.scene + "`\n\n";
  if (!scenario.description.empty()) md += scenario.description + "\n\n";
  md += "## Results\n\n| quantity | value | unit | meaning |\n|---|---:|---|---|\n";
  for (const auto& s : results.scalars)
    md += "| " + markdownTableCell(s.name) + " | " + formatNumber(s.value) + " | " + markdownTableCell(s.unit) +
          " | " + markdownTableCell(s.description) + " |\n";
  const auto& st = results.stats;
  md += "\n## Solver\n\n- method: " + (st.method.empty() ? std::string("-") : st.method) +
        "\n- steps: " + std::to_string(st.steps) + " (rejected " + std::to_string(st.rejected_steps) +
        ")\n- right-hand-side evaluations: " + std::to_string(st.rhs_evaluations) +
        "\n- error estimate: " + formatNumber(st.error_estimate) + " " + st.error_unit +
        "\n- wall time: " + formatNumber(st.wall_time_s) + " s\n";
  if (!results.warnings.empty()) {
    md += "\n## Warnings\n\n";
    for (const auto& w : results.warnings) md += "- " + w + "\n";
  }
  md += "\n## Files\n\n";
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    if (f.extension() == ".png")
      md += "![" + name + "](" + name + ")\n\n";
    else
      md += "- [" + name + "](" + name + ")\n";
  }
  return md;
}

std::vector<std::filesystem::path> writeReportFolder(const std::filesystem::path& dir, const Scenario& scenario,
                                                     const Results& results,
                                                     std::chrono::system_clock::time_point started_at,
                                                     const QImage& view3d) {
  // Staged and renamed into place as a whole (core/run_folder.hpp); a report of a run replaces the earlier
  // report of the same name, never a folder of other files.
  RunFolder folder(dir, {.replace = true});
  const std::filesystem::path staging = folder.staging();
  auto files = writeRunFolder(staging, scenario, results, started_at);
  for (const auto& spec : results.plots) {
    for (const char* suffix : {".png", ".pdf"}) {
      const auto file = staging / (spec.name + suffix);
      if (!savePlotImage(results, spec, QString::fromStdString(file.string()), 1200, 800))
        throw std::runtime_error("could not write plot " + file.string());
      files.push_back(file);
    }
  }
  if (!view3d.isNull()) {
    const auto file = staging / "view_3d.png";
    if (!view3d.save(QString::fromStdString(file.string()), "PNG"))
      throw std::runtime_error("could not write " + (dir / "view_3d.png").string());
    files.push_back(file);
  }
  const auto summary = staging / "summary.md";
  writeFileAtomic(summary, summaryMarkdown(scenario, results, files));
  files.push_back(summary);
  folder.commit();
  for (auto& f : files) f = folder.target() / f.filename();
  return files;
}

}  // namespace maris::ui
