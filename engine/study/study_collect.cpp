#include "study/study_collect.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "core/csv_field.hpp"
#include "core/results.hpp"
#include "core/input_limits.hpp"
#include "core/run_output.hpp"

namespace maris::study {

namespace {

std::string valueCell(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) return csvNumber(value.get<double>());
  return value.dump();  // integers, booleans, lists
}

bool isNumber(ParamKind kind) { return kind == ParamKind::Real || kind == ParamKind::Integer; }

std::string plainUnit(const std::string& unit) { return unit.empty() ? "-" : unit; }

// The scalars of a complete case's summary.json.
CaseScalars summaryScalars(const Json& j) {
  CaseScalars scalars;
  for (const auto& [name, s] : j.at("results").items())
    if (s.is_object() && s.contains("value") && s["value"].is_number())
      scalars[name] = {s["value"].get<double>(), s.value("unit", "-")};
  return scalars;
}

// The human labels a summary.json declares for its scalars (those without one are left out).
void addSummaryLabels(const Json& j, std::map<std::string, std::string>& labels) {
  for (const auto& [name, s] : j.at("results").items())
    if (s.is_object() && s.contains("label") && s["label"].is_string() && !s["label"].get<std::string>().empty())
      labels.emplace(name, s["label"].get<std::string>());
}

}  // namespace

std::size_t CollectedStudy::count(CaseStatus status) const {
  return static_cast<std::size_t>(
      std::count_if(cases.begin(), cases.end(), [status](const CollectedCase& c) { return c.status == status; }));
}

CollectedStudy collectStudy(const StudyFolder& folder, const StudyManifest& manifest) {
  std::vector<CollectedCase> cases;
  std::vector<CaseScalars> scalars(manifest.ids.size());
  std::map<std::string, std::string> labels;  // the first complete case's label of each scalar
  for (std::size_t i = 0; i < manifest.ids.size(); ++i) {
    CollectedCase c;
    c.id = manifest.ids[i];
    c.values = manifest.values[i];
    c.outcome.id = c.id;
    if (auto outcome = readCaseOutcome(folder, c.id)) c.outcome = *outcome;
    if (const auto summary = folder.caseSummary(c.id)) {
      try {
        scalars[i] = summaryScalars(*summary);
        addSummaryLabels(*summary, labels);
        c.status = CaseStatus::Ok;
        c.outcome.status = CaseStatus::Ok;
      } catch (const std::exception& e) {
        c.status = CaseStatus::Failed;
        c.outcome.message = std::string("summary.json cannot be read: ") + e.what();
      }
    } else if (c.outcome.status == CaseStatus::Failed || c.outcome.status == CaseStatus::Timeout) {
      c.status = c.outcome.status;
    }
    cases.push_back(std::move(c));
  }
  CollectedStudy collected = collectScalars(manifest.parameters, manifest.results, std::move(cases), scalars);
  for (const auto& name : collected.result_names) collected.result_labels.push_back(labels.count(name) ? labels[name] : "");
  if (!manifest.weight_column.empty())
    collected.weighted_sums = weightedSums(manifest.weighted_results, manifest.weights, collected.cases, scalars);
  return collected;
}

std::vector<WeightedSum> weightedSums(const std::vector<std::string>& results, const std::vector<double>& weights,
                                      const std::vector<CollectedCase>& cases, const std::vector<CaseScalars>& scalars) {
  std::vector<WeightedSum> sums;
  for (const auto& name : results) {
    WeightedSum sum;
    sum.result = name;
    sum.unit = "-";
    double total = 0.0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const double weight = i < weights.size() ? weights[i] : 0.0;
      sum.weight_total += weight;
      const std::pair<double, std::string>* value = nullptr;  // (value, unit)
      if (cases[i].status == CaseStatus::Ok && i < scalars.size())
        if (const auto it = scalars[i].find(name); it != scalars[i].end()) value = &it->second;
      if (value) sum.unit = value->second;
      if (weight == 0.0) continue;
      if (value)
        total += weight * value->first;
      else
        sum.missing.push_back(cases[i].id);
    }
    if (sum.missing.empty()) sum.value = total;
    sums.push_back(std::move(sum));
  }
  return sums;
}

CollectedStudy collectScalars(std::vector<StudyParameter> parameters, const std::vector<std::string>& requested,
                              std::vector<CollectedCase> cases, const std::vector<CaseScalars>& scalars) {
  CollectedStudy collected;
  collected.parameters = std::move(parameters);
  collected.cases = std::move(cases);
  std::map<std::string, std::string> units;  // every scalar name of the complete cases, with its unit
  for (std::size_t i = 0; i < collected.cases.size() && i < scalars.size(); ++i)
    if (collected.cases[i].status == CaseStatus::Ok)
      for (const auto& [name, value] : scalars[i]) units.emplace(name, value.second);
  if (requested.empty()) {
    for (const auto& [name, unit] : units) collected.result_names.push_back(name);
  } else {
    collected.result_names = requested;
    std::vector<std::string> known;
    for (const auto& [name, unit] : units) known.push_back(name);
    for (const auto& name : requested) {
      if (units.count(name) || known.empty()) continue;
      const auto guess = didYouMean(name, known);
      collected.warnings.push_back("result '" + name + "' is in no complete case's summary.json" +
                                   (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
    }
  }
  for (const auto& name : collected.result_names) collected.result_units.push_back(units.count(name) ? units[name] : "-");
  for (std::size_t i = 0; i < collected.cases.size(); ++i)
    for (const auto& name : collected.result_names) {
      std::optional<double> value;
      if (collected.cases[i].status == CaseStatus::Ok && i < scalars.size())
        if (const auto it = scalars[i].find(name); it != scalars[i].end()) value = it->second.first;
      collected.cases[i].results.push_back(value);
    }
  return collected;
}

std::string studyCsv(const CollectedStudy& collected) {
  std::string out = "case,status";
  for (const auto& p : collected.parameters) appendCsvField(out += ',', p.path);
  for (const auto& name : collected.result_names) appendCsvField(out += ',', name);
  out += "\n-,-";
  for (const auto& p : collected.parameters) appendCsvField(out += ',', plainUnit(p.unit));
  for (const auto& unit : collected.result_units) appendCsvField(out += ',', plainUnit(unit));
  out += '\n';
  for (const auto& c : collected.cases) {
    out += c.id;
    out += ',';
    out += toString(c.status);
    for (const auto& v : c.values) appendCsvField(out += ',', valueCell(v));
    for (const auto& r : c.results) {
      out += ',';
      if (r) out += csvNumber(*r);
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
  if (!collected.weighted_sums.empty()) {
    Json sums = Json::array();
    for (const auto& sum : collected.weighted_sums)
      sums.push_back({{"result", sum.result},
                      {"weight", manifest.weight_column},
                      {"value", sum.value ? Json(*sum.value) : Json()},
                      {"unit", sum.unit},
                      {"weight_total", sum.weight_total},
                      {"missing", sum.missing}});
    manifest.json["collected"]["weighted_sums"] = std::move(sums);
  }
  writeFileAtomic(folder.manifest(), manifest.json.dump(1) + "\n");
}

namespace {

// `name` as a file name every file system and shell takes: a cell's "[ROW]" becomes "_ROW" and any other
// character outside [A-Za-z0-9._-] a '_'; a leading '.' or '-' (a hidden file, an option) gets a '_' before it.
std::string portableStem(const std::string& name) {
  std::string stem;
  for (const char c : name) {
    if (c == ']') continue;
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
                       c == '_' || c == '-';
    stem += plain ? c : '_';
  }
  if (stem.empty() || stem.front() == '.' || stem.front() == '-') stem.insert(stem.begin(), '_');
  return stem;
}

// Makes every plot's file stem unique, ignoring case (two stems that differ only in case are one file on
// macOS and Windows): a later repeat gets "-2", "-3", … in the order of the plots.
void makeStemsUnique(std::vector<StudyPlot>& plots) {
  const auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  std::set<std::string> taken;
  for (const auto& plot : plots) taken.insert(lower(plot.file_stem));
  std::set<std::string> used;
  for (auto& plot : plots) {
    if (used.insert(lower(plot.file_stem)).second) continue;
    for (int n = 2;; ++n) {
      const std::string candidate = plot.file_stem + "-" + std::to_string(n);
      if (taken.count(lower(candidate)) || used.count(lower(candidate))) continue;
      plot.file_stem = candidate;
      used.insert(lower(candidate));
      break;
    }
  }
}

}  // namespace

std::vector<StudyPlot> studyPlots(const CollectedStudy& collected, const StudyManifest& manifest) {
  std::vector<StudyPlot> plots;
  std::vector<std::size_t> numeric;
  for (std::size_t p = 0; p < collected.parameters.size(); ++p)
    if (isNumber(collected.parameters[p].kind)) numeric.push_back(p);
  const bool map = manifest.json.value("design", "") == "grid" && collected.parameters.size() == 2 && numeric.size() == 2;
  for (std::size_t r = 0; r < collected.result_names.size(); ++r) {
    const std::string& result = collected.result_names[r];
    // Titles name the result and the parameters by their labels for people (the result's as the runs declared
    // it, the parameters' from the scene's schema), where there are none by their names; file names by paths.
    const std::string shown =
        r < collected.result_labels.size() && !collected.result_labels[r].empty() ? collected.result_labels[r]
                                                                                   : readableName(result);
    if (map)
      plots.push_back({portableStem(result + "_map"), shown + " over " + displayLabel(collected.parameters[0]) +
                                                          " and " + displayLabel(collected.parameters[1]),
                       r, 1, true});
    for (const auto p : numeric)
      plots.push_back({portableStem(result + "_vs_" + collected.parameters[p].path),
                       shown + " against " + displayLabel(collected.parameters[p]), r, p, false});
  }
  makeStemsUnique(plots);
  return plots;
}

bool logSpaced(const Json& document, const std::string& path) {
  for (const char* design : {"grid", "latin_hypercube"}) {
    const auto d = document.find(design);
    if (d == document.end() || !d->is_object()) continue;
    const Json& entries = d->contains("bounds") ? d->at("bounds") : *d;
    const auto e = entries.find(path);
    if (e != entries.end() && e->is_object() && e->value("spacing", "") == "log") return true;
  }
  return false;
}

}  // namespace maris::study
