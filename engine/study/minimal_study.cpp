#include "study/minimal_study.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/csv_field.hpp"
#include "core/errors.hpp"
#include "core/input_limits.hpp"
#include "core/text_format.hpp"

namespace maris::study {

namespace {

constexpr int kMaxValues = 100000;
constexpr std::size_t kMaxCases = 1000000;

std::string caseId(std::size_t index) { return formatText("%04zu", index + 1); }

std::string number(double v) { return formatText("%.17g", v); }

// A grid entry: a list of numbers, or {from, to, count, spacing}.
GridParameter gridParameterFromJson(const std::string& path, const Json& j, std::vector<FieldError>& errors) {
  GridParameter g;
  g.path = path;
  const std::string where = "grid." + path;
  if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      if (!j[i].is_number())
        errors.push_back({where + "[" + std::to_string(i) + "]", jsonSnippet(j[i]), "must be a number"});
      else
        g.values.push_back(j[i].get<double>());
    }
    if (j.empty()) errors.push_back({where, "[]", "must list at least one value"});
    return g;
  }
  if (!j.is_object()) {
    errors.push_back({where, jsonSnippet(j), "must be a list of values or {from, to, count, spacing}"});
    return g;
  }
  auto num = [&](const char* key, double& out) {
    const auto it = j.find(key);
    if (it == j.end())
      errors.push_back({where + "." + key, "", "is missing (a number)"});
    else if (!it->is_number())
      errors.push_back({where + "." + key, jsonSnippet(*it), "must be a number"});
    else
      out = it->get<double>();
  };
  num("from", g.from);
  num("to", g.to);
  double count = 0.0;
  num("count", count);
  g.count = count >= 1 && count <= kMaxValues && count == std::floor(count) ? static_cast<int>(count) : 0;
  if (j.contains("count") && j["count"].is_number() && g.count == 0)
    errors.push_back({where + ".count", jsonSnippet(j["count"]), formatText("must be a whole number in [1, %d]", kMaxValues)});
  if (const auto it = j.find("spacing"); it != j.end()) {
    if (*it == "log")
      g.log = true;
    else if (*it != "linear")
      errors.push_back({where + ".spacing", jsonSnippet(*it), "must be \"linear\" or \"log\""});
  }
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "from" && it.key() != "to" && it.key() != "count" && it.key() != "spacing")
      errors.push_back({where + "." + it.key(), jsonSnippet(it.value()), "unknown field (from, to, count, spacing)"});
  return g;
}

}  // namespace

std::vector<double> gridValues(const GridParameter& g) {
  if (!g.values.empty()) return g.values;
  const std::string where = "grid." + g.path;
  if (g.count < 1 || g.count > kMaxValues)
    throw InputError(where + ".count", std::to_string(g.count), formatText("must be in [1, %d]", kMaxValues));
  if (!std::isfinite(g.from) || !std::isfinite(g.to)) throw InputError(where, "", "from and to must be finite numbers");
  if (g.log && (g.from <= 0.0 || g.to <= 0.0))
    throw InputError(where, number(g.log ? std::min(g.from, g.to) : 0.0), "a log spacing needs from and to > 0");
  std::vector<double> values(g.count);
  for (int i = 0; i < g.count; ++i) {
    const double t = g.count == 1 ? 0.0 : static_cast<double>(i) / (g.count - 1);
    values[i] = g.log ? std::exp(std::log(g.from) + t * (std::log(g.to) - std::log(g.from))) : g.from + t * (g.to - g.from);
  }
  // The ends exactly as given (no rounding in the last digit).
  values.front() = g.from;
  values.back() = g.count == 1 ? g.from : g.to;
  return values;
}

Json studyToJson(const StudyDefinition& study) {
  Json doc = Json::object();
  doc["format"] = kStudyFormat;
  if (!study.name.empty()) doc["name"] = study.name;
  if (!study.description.empty()) doc["description"] = study.description;
  doc["base"] = Json{{"scenario", scenarioToJson(study.base)}};
  Json grid = Json::object();
  for (const GridParameter& g : study.grid) {
    if (!g.values.empty())
      grid[g.path] = g.values;
    else
      grid[g.path] = Json{{"from", g.from}, {"to", g.to}, {"count", g.count}, {"spacing", g.log ? "log" : "linear"}};
  }
  doc["grid"] = grid;
  if (!study.results.empty()) doc["results"] = study.results;
  return doc;
}

StudyDefinition studyFromJson(const Json& doc, const std::function<const Scenario*(const std::string&)>& builtin,
                              const std::filesystem::path& folder) {
  if (!doc.is_object()) throw InputError("(document)", jsonSnippet(doc), "a study must be a JSON object");
  std::vector<FieldError> errors;
  StudyDefinition s;
  if (!doc.contains("format") || doc["format"] != kStudyFormat)
    errors.push_back({"format", doc.contains("format") ? jsonSnippet(doc["format"]) : "",
                      std::string("must be \"") + kStudyFormat + "\""});
  if (doc.contains("name") && doc["name"].is_string()) s.name = doc["name"].get<std::string>();
  if (doc.contains("description") && doc["description"].is_string()) s.description = doc["description"].get<std::string>();
  const auto base = doc.find("base");
  if (base == doc.end() || !base->is_object() || base->size() != 1) {
    errors.push_back({"base", base == doc.end() ? "" : jsonSnippet(*base),
                      "must be one of {\"scenario\": {...}}, {\"builtin\": NAME}, {\"file\": PATH}"});
  } else {
    try {
      if (base->contains("scenario")) {
        s.base = scenarioFromJson((*base)["scenario"]);
      } else if (base->contains("builtin") && (*base)["builtin"].is_string()) {
        const std::string id = (*base)["builtin"].get<std::string>();
        const Scenario* found = builtin ? builtin(id) : nullptr;
        if (!found) throw InputError("base.builtin", id, "is not a built-in scenario (maris-cli list)");
        s.base = *found;
      } else if (base->contains("file") && (*base)["file"].is_string()) {
        std::filesystem::path path = (*base)["file"].get<std::string>();
        s.base = loadScenarioFile(path.is_relative() ? folder / path : path);
      } else {
        errors.push_back({"base", jsonSnippet(*base), "must be one of {\"scenario\": {...}}, {\"builtin\": NAME}, {\"file\": PATH}"});
      }
    } catch (const InputError& e) {
      for (FieldError f : e.errors()) {
        f.path = "base." + f.path;
        errors.push_back(std::move(f));
      }
    }
  }
  const auto grid = doc.find("grid");
  if (grid == doc.end() || !grid->is_object() || grid->empty())
    errors.push_back({"grid", grid == doc.end() ? "" : jsonSnippet(*grid),
                      "must map parameter paths to values (this program reads grid studies only)"});
  else
    for (auto it = grid->begin(); it != grid->end(); ++it) s.grid.push_back(gridParameterFromJson(it.key(), it.value(), errors));
  if (const auto r = doc.find("results"); r != doc.end()) {
    if (!r->is_array()) errors.push_back({"results", jsonSnippet(*r), "must be a list of scalar names"});
    else
      for (const Json& name : *r)
        if (name.is_string()) s.results.push_back(name.get<std::string>());
        else errors.push_back({"results", jsonSnippet(name), "must be a scalar's name (text)"});
  }
  static const std::vector<std::string> known = {"format", "name", "description", "base", "grid", "results"};
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (std::find(known.begin(), known.end(), it.key()) == known.end())
      errors.push_back({it.key(), jsonSnippet(it.value()), "unknown field (format, name, description, base, grid, results)"});
  if (!errors.empty()) throw InputError(std::move(errors));
  return s;
}

StudyDefinition loadStudyFile(const std::filesystem::path& file,
                              const std::function<const Scenario*(const std::string&)>& builtin) {
  const std::string text = readTextFile(file);
  return studyFromJson(parseJsonLimited(text, file.string()), builtin, file.parent_path());
}

void saveStudyFile(const StudyDefinition& study, const std::filesystem::path& file) {
  writeFileAtomic(file, studyToJson(study).dump(2) + "\n");
}

std::vector<StudyCase> expandStudy(const StudyDefinition& study, const SceneDefinition& scene) {
  std::vector<FieldError> errors;
  std::vector<std::vector<double>> values;
  std::size_t total = 1;
  for (const GridParameter& g : study.grid) {
    const ParamSpec* spec = scene.schema.find(g.path);
    if (!spec || (spec->kind != ParamKind::Real && spec->kind != ParamKind::Integer))
      errors.push_back({"grid." + g.path, "", "is not a number field of the scene " + scene.name});
    try {
      values.push_back(gridValues(g));
      total *= values.back().size();
    } catch (const InputError& e) {
      errors.insert(errors.end(), e.errors().begin(), e.errors().end());
      values.emplace_back();
    }
  }
  if (study.grid.empty()) errors.push_back({"grid", "{}", "must vary at least one parameter"});
  if (errors.empty() && total > kMaxCases)
    errors.push_back({"grid", std::to_string(total) + " cases", formatText("more than %zu cases", kMaxCases)});
  if (!errors.empty()) throw InputError(std::move(errors));
  std::vector<StudyCase> cases(total);
  for (std::size_t c = 0; c < total; ++c) {
    StudyCase& sc = cases[c];
    sc.id = caseId(c);
    sc.scenario = study.base;
    sc.scenario.name = study.base.name + " [case " + sc.id + "]";
    std::size_t rest = c;
    sc.values.resize(study.grid.size());
    for (std::size_t p = study.grid.size(); p-- > 0;) {
      sc.values[p] = values[p][rest % values[p].size()];
      rest /= values[p].size();
      const ParamSpec* spec = scene.schema.find(study.grid[p].path);
      const Json v = spec->kind == ParamKind::Integer ? Json(static_cast<long long>(std::llround(sc.values[p])))
                                                      : Json(sc.values[p]);
      setAtPath(sc.scenario.parameters, study.grid[p].path, v);
    }
    for (FieldError e : validateParameters(scene, sc.scenario.parameters)) {
      e.path = "case " + sc.id + ": " + e.path;
      errors.push_back(std::move(e));
    }
  }
  if (!errors.empty()) throw InputError(std::move(errors));
  return cases;
}

std::string studyCsv(const StudyDefinition& study, const SceneDefinition& scene, const std::vector<StudyCase>& cases,
                     const std::vector<CaseResult>& outcomes) {
  std::vector<std::string> scalars = study.results;
  std::map<std::string, std::string> units;
  for (const CaseResult& o : outcomes)
    if (o.results)
      for (const Scalar& s : o.results->scalars) {
        if (study.results.empty() && std::find(scalars.begin(), scalars.end(), s.name) == scalars.end())
          scalars.push_back(s.name);
        units.emplace(s.name, s.unit);
      }
  std::string names = "case,status", unit_row = "-,-";
  for (const GridParameter& g : study.grid) {
    const ParamSpec* spec = scene.schema.find(g.path);
    names += ',';
    appendCsvField(names, g.path);
    unit_row += ',';
    appendCsvField(unit_row, spec && !spec->unit.empty() ? spec->unit : "-");
  }
  for (const std::string& s : scalars) {
    names += ',';
    appendCsvField(names, s);
    unit_row += ',';
    appendCsvField(unit_row, units.count(s) && !units[s].empty() ? units[s] : "-");
  }
  std::string out = names + "\n" + unit_row + "\n";
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const CaseResult* o = c < outcomes.size() ? &outcomes[c] : nullptr;
    out += cases[c].id + "," + (o ? o->status : std::string("pending"));
    for (double v : cases[c].values) out += "," + number(v);
    for (const std::string& s : scalars) {
      out += ',';
      if (const Scalar* found = o && o->results ? o->results->findScalar(s) : nullptr) out += number(found->value);
    }
    out += '\n';
  }
  return out;
}

}  // namespace maris::study
