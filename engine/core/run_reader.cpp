#include "core/run_reader.hpp"

#include <cmath>

#include "core/input_limits.hpp"
#include "core/table_reader.hpp"

namespace maris {

namespace {

PlotSpec plotFromJson(const Json& j) {
  PlotSpec p;
  p.name = j.value("name", std::string());
  p.title = j.value("title", std::string());
  p.table = j.value("table", std::string());
  p.x = j.value("x", std::string());
  p.y = j.value("y", std::vector<std::string>());
  p.log_x = j.value("log_x", false);
  p.log_y = j.value("log_y", false);
  p.reference_table = j.value("reference_table", std::string());
  p.reference_y = j.value("reference_y", std::vector<std::string>());
  return p;
}

// A plot whose table or columns the folder lacks would draw nothing: left out.
bool drawable(const Results& results, const PlotSpec& p) {
  const Table* t = results.findTable(p.table);
  if (!t || !t->find(p.x) || p.y.empty()) return false;
  for (const auto& y : p.y)
    if (!t->find(y)) return false;
  return true;
}

}  // namespace

RunFolderContents readRunFolder(const std::filesystem::path& dir) {
  const auto summary_file = dir / "summary.json";
  const Json summary = parseJsonLimited(readInputFile(summary_file, summary_file.string(), InputLimits::kScenarioFileBytes),
                                        summary_file.string());
  if (!summary.is_object()) throw InputError(summary_file.string(), "", "is not a run's summary (a JSON object)");
  RunFolderContents out;
  Results& r = out.results;
  try {
    if (const auto s = summary.find("results"); s != summary.end() && s->is_object())
      for (const auto& [name, value] : s->items())
        if (value.is_object() && value.contains("value") && value["value"].is_number())
          r.addScalar(name, value["value"].get<double>(), value.value("unit", std::string("-")),
                      value.value("description", std::string()), value.value("label", std::string()));
    if (const auto w = summary.find("warnings"); w != summary.end() && w->is_array())
      for (const auto& text : *w)
        if (text.is_string()) r.warnings.push_back(text.get<std::string>());
    if (const auto s = summary.find("solver"); s != summary.end() && s->is_object()) {
      r.stats.method = s->value("method", std::string());
      r.stats.steps = s->value("steps", 0L);
      r.stats.rejected_steps = s->value("rejected_steps", 0L);
      r.stats.rhs_evaluations = s->value("rhs_evaluations", 0L);
      if (const auto wall = s->find("wall_time"); wall != s->end() && wall->is_object())
        r.stats.wall_time_s = wall->value("value", 0.0);
      if (const auto e = s->find("error_estimate"); e != s->end() && e->is_object()) {
        r.stats.error_estimate = e->value("value", 0.0);
        r.stats.error_unit = e->value("unit", std::string());
      }
    }
    const Json labels = summary.value("table_labels", Json::object());
    for (const auto& file : summary.value("tables", std::vector<std::string>())) {
      // Only plain file names: summary.json names the CSV files beside it.
      if (file.find('/') != std::string::npos || file.size() < 5 || file.substr(file.size() - 4) != ".csv")
        throw InputError(summary_file.string(), "", "lists \"" + file + "\", not a table file beside it");
      const auto path = dir / file;
      TableSpec spec;
      spec.field = summary_file.string() + " tables";
      spec.file = path.string();
      spec.expected = "a run's table: a row of names, a row of units, rows of numbers";
      spec.empty_cells = true;  // a column shorter than the others
      const TextTable text = parseTable(readInputFile(path, path.string(), InputLimits::kDataFileBytes), spec);
      Table t;
      t.name = file.substr(0, file.size() - 4);
      const Json about = labels.is_object() ? labels.value(t.name, Json::object()) : Json::object();
      t.title = about.value("title", std::string());
      const Json column_labels = about.value("columns", Json::object());
      for (std::size_t c = 0; c < text.columns(); ++c) {
        std::vector<double> values;
        values.reserve(text.rows.size());
        for (const auto& row : text.rows)
          if (c < row.cells.size() && row.cells[c]) values.push_back(*row.cells[c]);
        const std::string& name = text.names[c];
        const std::string unit = text.units.size() > c && !text.units[c].empty() ? text.units[c] : "-";
        t.add(name, unit, std::move(values),
              column_labels.is_object() ? column_labels.value(name, std::string()) : std::string());
      }
      r.tables.push_back(std::move(t));
    }
    if (const auto plots = summary.find("plots"); plots != summary.end() && plots->is_array()) {
      for (const auto& p : *plots) {
        if (!p.is_object()) continue;
        PlotSpec spec = plotFromJson(p);
        if (drawable(r, spec)) r.plots.push_back(std::move(spec));
      }
    } else {
      out.missing.push_back("the plots' layouts (this run folder was written by Maris 0.9.0 or earlier: its tables are shown)");
    }
  } catch (const Json::exception& e) {
    throw InputError(summary_file.string(), "", std::string("is damaged: ") + e.what());
  }
  out.missing.push_back("the 3D view (a run folder stores none; run the case again to see it)");
  return out;
}

}  // namespace maris
