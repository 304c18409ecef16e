#include "study/study_collect.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include "core/input_limits.hpp"
#include "core/run_output.hpp"

namespace maris::study {

namespace {

void appendCell(std::string& out, const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) {
    out += text;
    return;
  }
  out += '"';
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  out += '"';
}

std::string valueCell(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) return numberCell(value.get<double>());
  return value.dump();  // integers, booleans, lists
}

bool isNumber(ParamKind kind) { return kind == ParamKind::Real || kind == ParamKind::Integer; }

std::string plainUnit(const std::string& unit) { return unit.empty() ? "-" : unit; }

// The scalars of a complete case's summary.json: name -> (value, unit).
std::map<std::string, std::pair<double, std::string>> readScalars(const std::filesystem::path& summary) {
  const Json j = parseJsonLimited(readInputFile(summary, summary.string(), InputLimits::kScenarioFileBytes),
                                  summary.string());
  std::map<std::string, std::pair<double, std::string>> scalars;
  for (const auto& [name, s] : j.at("results").items())
    if (s.is_object() && s.contains("value") && s["value"].is_number())
      scalars[name] = {s["value"].get<double>(), s.value("unit", "-")};
  return scalars;
}

}  // namespace

std::string numberCell(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17);
  return std::string(text, result.ptr);
}

std::size_t CollectedStudy::count(CaseStatus status) const {
  return static_cast<std::size_t>(
      std::count_if(cases.begin(), cases.end(), [status](const CollectedCase& c) { return c.status == status; }));
}

CollectedStudy collectStudy(const StudyFolder& folder, const StudyManifest& manifest) {
  CollectedStudy collected;
  collected.parameters = manifest.parameters;
  std::vector<std::map<std::string, std::pair<double, std::string>>> scalars(manifest.ids.size());
  std::map<std::string, std::string> units;  // every scalar name of the complete cases, with its unit
  for (std::size_t i = 0; i < manifest.ids.size(); ++i) {
    CollectedCase c;
    c.id = manifest.ids[i];
    c.values = manifest.values[i];
    c.outcome.id = c.id;
    if (auto outcome = readCaseOutcome(folder, c.id)) c.outcome = *outcome;
    if (folder.caseComplete(c.id)) {
      try {
        scalars[i] = readScalars(folder.caseRun(c.id) / "summary.json");
        c.status = CaseStatus::Ok;
        c.outcome.status = CaseStatus::Ok;
        for (const auto& [name, value] : scalars[i]) units.emplace(name, value.second);
      } catch (const std::exception& e) {
        c.status = CaseStatus::Failed;
        c.outcome.message = std::string("summary.json cannot be read: ") + e.what();
      }
    } else if (c.outcome.status == CaseStatus::Failed || c.outcome.status == CaseStatus::Timeout) {
      c.status = c.outcome.status;
    }
    collected.cases.push_back(std::move(c));
  }
  if (manifest.results.empty()) {
    for (const auto& [name, unit] : units) collected.result_names.push_back(name);
  } else {
    collected.result_names = manifest.results;
    std::vector<std::string> known;
    for (const auto& [name, unit] : units) known.push_back(name);
    for (const auto& name : manifest.results) {
      if (units.count(name) || known.empty()) continue;
      const auto guess = didYouMean(name, known);
      collected.warnings.push_back("result '" + name + "' is in no complete case's summary.json" +
                                   (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
    }
  }
  for (const auto& name : collected.result_names) collected.result_units.push_back(units.count(name) ? units[name] : "-");
  for (std::size_t i = 0; i < collected.cases.size(); ++i)
    for (const auto& name : collected.result_names) {
      const auto it = scalars[i].find(name);
      collected.cases[i].results.push_back(it == scalars[i].end() ? std::nullopt : std::optional(it->second.first));
    }
  return collected;
}

std::string studyCsv(const CollectedStudy& collected) {
  std::string out = "case,status";
  for (const auto& p : collected.parameters) appendCell(out += ',', p.path);
  for (const auto& name : collected.result_names) appendCell(out += ',', name);
  out += "\n-,-";
  for (const auto& p : collected.parameters) appendCell(out += ',', plainUnit(p.unit));
  for (const auto& unit : collected.result_units) appendCell(out += ',', plainUnit(unit));
  out += '\n';
  for (const auto& c : collected.cases) {
    out += c.id;
    out += ',';
    out += toString(c.status);
    for (const auto& v : c.values) appendCell(out += ',', valueCell(v));
    for (const auto& r : c.results) {
      out += ',';
      if (r) out += numberCell(*r);
    }
    out += '\n';
  }
  return out;
}

void writeCollected(const StudyFolder& folder, StudyManifest& manifest, const CollectedStudy& collected) {
  writeFileAtomic(folder.csv(), studyCsv(collected));
  Json cases = Json::array();
  for (const auto& c : collected.cases) {
    Json j = {{"id", c.id}, {"status", toString(c.status)}};
    if (c.status != CaseStatus::Missing) {
      j["exit_code"] = c.outcome.exit_code;
      j["wall_s"] = c.outcome.wall_s;
      if (!c.outcome.started_at.empty()) j["started_at"] = c.outcome.started_at;
    }
    if (!c.outcome.message.empty() && c.status != CaseStatus::Ok) j["message"] = c.outcome.message;
    cases.push_back(std::move(j));
  }
  manifest.json["collected"] = {{"at", isoUtc(std::chrono::system_clock::now())},
                                {"ok", collected.count(CaseStatus::Ok)},
                                {"failed", collected.count(CaseStatus::Failed)},
                                {"timeout", collected.count(CaseStatus::Timeout)},
                                {"missing", collected.count(CaseStatus::Missing)},
                                {"results", collected.result_names},
                                {"warnings", collected.warnings},
                                {"cases", cases}};
  writeFileAtomic(folder.manifest(), manifest.json.dump(1) + "\n");
}

std::vector<StudyPlot> studyPlots(const CollectedStudy& collected, const StudyManifest& manifest) {
  std::vector<StudyPlot> plots;
  std::vector<std::size_t> numeric;
  for (std::size_t p = 0; p < collected.parameters.size(); ++p)
    if (isNumber(collected.parameters[p].kind)) numeric.push_back(p);
  const bool map = manifest.json.value("design", "") == "grid" && collected.parameters.size() == 2 && numeric.size() == 2;
  for (std::size_t r = 0; r < collected.result_names.size(); ++r) {
    const std::string& result = collected.result_names[r];
    if (map) {
      StudyPlot plot;
      const auto& px = collected.parameters[1];  // the grid's fastest parameter across, the other up
      const auto& py = collected.parameters[0];
      plot.file_stem = result + "_map";
      plot.title = result + " over " + py.path + " and " + px.path;
      plot.heat_map = true;
      plot.x_name = px.path, plot.x_unit = px.unit, plot.y_name = py.path, plot.y_unit = py.unit;
      plot.z_name = result, plot.z_unit = collected.result_units[r];
      std::map<double, std::size_t> xs, ys;
      for (const auto& c : collected.cases) {
        xs.emplace(c.values[1].get<double>(), 0);
        ys.emplace(c.values[0].get<double>(), 0);
      }
      for (auto& [v, i] : xs) i = plot.x.size(), plot.x.push_back(v);
      for (auto& [v, i] : ys) i = plot.y.size(), plot.y.push_back(v);
      plot.z.assign(plot.x.size() * plot.y.size(), std::nan(""));
      for (const auto& c : collected.cases)
        if (c.results[r])
          plot.z[ys[c.values[0].get<double>()] * plot.x.size() + xs[c.values[1].get<double>()]] = *c.results[r];
      plots.push_back(std::move(plot));
      continue;
    }
    for (const auto p : numeric) {
      const auto& param = collected.parameters[p];
      StudyPlot plot;
      plot.file_stem = result + "_vs_" + param.path;
      plot.title = result + " against " + param.path;
      plot.x_name = param.path, plot.x_unit = param.unit, plot.y_name = result, plot.y_unit = collected.result_units[r];
      plot.line = collected.parameters.size() == 1;
      std::vector<std::pair<double, double>> points;
      for (const auto& c : collected.cases)
        if (c.results[r]) points.emplace_back(c.values[p].get<double>(), *c.results[r]);
      if (points.empty()) continue;
      if (plot.line) std::sort(points.begin(), points.end());
      for (const auto& [x, y] : points) plot.x.push_back(x), plot.y.push_back(y);
      plots.push_back(std::move(plot));
    }
  }
  return plots;
}

}  // namespace maris::study
