// Reading a study document: the envelope, the base scenario and which design it uses.
#include <algorithm>
#include <system_error>

#include "catalog.hpp"
#include "core/input_limits.hpp"
#include "core/resources.hpp"
#include "study/study.hpp"
#include "study/study_design.hpp"
#include "study/study_folder.hpp"

namespace maris::study {

namespace {

const std::vector<std::string> kDesigns = {"grid", "table", "latin_hypercube"};
const std::vector<std::string> kFields = {"format", "name", "description", "base", "set", "results",
                                          "grid", "table", "latin_hypercube", "weighted_sum"};

void prefixErrors(const std::vector<FieldError>& from, const std::string& prefix, std::vector<FieldError>& to) {
  for (auto e : from) {
    e.path = prefix + e.path;
    to.push_back(std::move(e));
  }
}

void readText(const Json& document, const char* key, std::string& out, std::vector<FieldError>& errors) {
  const auto it = document.find(key);
  if (it == document.end()) return;
  if (it->is_string())
    out = it->get<std::string>();
  else
    errors.push_back({key, jsonSnippet(*it), "must be a text string"});
}

// The base scenario: a file beside the study (relative to its folder), a built-in scenario's name, or
// a scenario object written into the study. Its data paths become absolute against its own file's folder.
// The desktop application's first study files wrote the base as {"scenario": {...}}, {"builtin": name} or
// {"file": path}: read as the plain forms.
bool readBase(const Json& base, const SceneSource& source, Study& study, std::vector<FieldError>& errors) {
  if (base.is_object() && base.size() == 1) {
    for (const char* key : {"scenario", "builtin", "file"})
      if (base.contains(key)) return readBase(base.at(key), source, study, errors);
  }
  if (base.is_object()) {
    try {
      study.base = scenarioFromJson(base);
    } catch (const InputError& e) {
      prefixErrors(e.errors(), "base.", errors);
      return false;
    }
    study.base_origin = "inline";
    return true;
  }
  if (!base.is_string() || base.get<std::string>().empty()) {
    errors.push_back({"base", jsonSnippet(base),
                      "must be a built-in scenario's name, a scenario file (relative to the study's folder) or a "
                      "scenario object"});
    return false;
  }
  const std::string name = base.get<std::string>();
  const std::filesystem::path file = study.folder / name;
  std::error_code error;
  if (std::filesystem::exists(std::filesystem::symlink_status(file, error))) {
    try {
      study.base = loadScenarioFile(file);
    } catch (const InputError& e) {
      prefixErrors(e.errors(), "base (" + echoText(file.string()) + "): ", errors);
      return false;
    }
    study.base_origin = "file " + file.lexically_normal().string();
    if (const auto* scene = source.scene(study.base.scene))
      resolveDataPaths(scene->schema, study.base.parameters, file.lexically_normal().parent_path());
    return true;
  }
  if (const auto* builtin = source.builtin(name)) {
    study.base = *builtin;
    study.base_origin = "built-in " + name;
    return true;
  }
  const auto guess = didYouMean(name, source.builtin_ids());
  errors.push_back({"base", jsonSnippet(base),
                    "is neither a file in " + echoText(study.folder.string()) +
                        " nor a built-in scenario (see `maris-cli list`)" +
                        (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
  return false;
}

// "set": fixed values written into the base before the cases vary it.
void applySet(const Json& set, const SceneDefinition& scene, Study& study, std::vector<FieldError>& errors) {
  if (!set.is_object()) {
    errors.push_back({"set", jsonSnippet(set), "must be an object of parameter paths and values"});
    return;
  }
  for (auto it = set.begin(); it != set.end(); ++it) {
    const std::string where = "set." + it.key();
    const auto spec = detail::lookupParameter(scene, study.base.parameters, it.key(), where, errors, true);
    if (spec) detail::setParameter(study.base.parameters, spec->path, it.value());
  }
}

void readResults(const Json& results, Study& study, std::vector<FieldError>& errors) {
  if (!results.is_array()) {
    errors.push_back({"results", jsonSnippet(results), "must be a list of scalar result names"});
    return;
  }
  for (std::size_t i = 0; i < results.size(); ++i) {
    const std::string where = "results[" + std::to_string(i) + "]";
    if (!results[i].is_string() || results[i].get<std::string>().empty()) {
      errors.push_back({where, jsonSnippet(results[i]), "must be a scalar result's name (see a run's summary.json)"});
      continue;
    }
    const std::string name = results[i].get<std::string>();
    if (std::find(study.results.begin(), study.results.end(), name) != study.results.end())
      errors.push_back({where, jsonSnippet(results[i]), "is listed twice"});
    else
      study.results.push_back(name);
  }
}

// "weighted_sum": {"weight": COLUMN, "results": [...]}, for a table study (its column is read with the table).
void readWeightedSum(const Json& sum, bool table, Study& study, std::vector<FieldError>& errors) {
  if (!table) {
    errors.push_back({"weighted_sum", jsonSnippet(sum), "needs a \"table\" design (the weights are a column of it)"});
    return;
  }
  if (!sum.is_object()) {
    errors.push_back({"weighted_sum", jsonSnippet(sum), "must be {\"weight\": COLUMN, \"results\": [scalar, ...]}"});
    return;
  }
  for (auto it = sum.begin(); it != sum.end(); ++it)
    if (it.key() != "weight" && it.key() != "results")
      errors.push_back({"weighted_sum." + it.key(), jsonSnippet(it.value()), "unknown field; expected weight, results"});
  const auto weight = sum.find("weight");
  if (weight == sum.end() || !weight->is_string() || weight->get<std::string>().empty())
    errors.push_back({"weighted_sum.weight", weight == sum.end() ? "" : jsonSnippet(*weight),
                      "must name a column of the table (its header) that holds each case's weight"});
  else
    study.weight_column = weight->get<std::string>();
  const auto results = sum.find("results");
  if (results == sum.end() || !results->is_array() || results->empty()) {
    errors.push_back({"weighted_sum.results", results == sum.end() ? "" : jsonSnippet(*results),
                      "must list the scalar results to sum (names as in a run's summary.json)"});
    return;
  }
  for (std::size_t i = 0; i < results->size(); ++i) {
    const Json& r = (*results)[i];
    const std::string where = "weighted_sum.results[" + std::to_string(i) + "]";
    if (!r.is_string() || r.get<std::string>().empty())
      errors.push_back({where, jsonSnippet(r), "must be a scalar result's name"});
    else if (std::find(study.weighted_results.begin(), study.weighted_results.end(), r.get<std::string>()) !=
             study.weighted_results.end())
      errors.push_back({where, jsonSnippet(r), "is listed twice"});
    else
      study.weighted_results.push_back(r.get<std::string>());
  }
}

}  // namespace

const char* toString(DesignKind kind) {
  switch (kind) {
    case DesignKind::Grid: return "grid";
    case DesignKind::Table: return "table";
    case DesignKind::LatinHypercube: return "latin_hypercube";
  }
  return "grid";
}

bool isStudyDocument(const Json& document) {
  if (!document.is_object()) return false;
  const auto it = document.find("format");
  // A study folder's record (its study.json) counts too, so that `validate` says what it is.
  return it != document.end() && it->is_string() &&
         (it->get<std::string>().rfind("maris-study/", 0) == 0 || it->get<std::string>() == kStudyRunFormat);
}

SceneSource catalogSource() {
  SceneSource source;
  source.scene = [](const std::string& name) { return findScene(name); };
  source.builtin = [](const std::string& id) -> const Scenario* {
    const BuiltinScenario* found = findBuiltin(id);
    return found ? &found->scenario : nullptr;
  };
  source.builtin_ids = [] {
    std::vector<std::string> ids;
    for (const auto& b : builtinScenarios()) ids.push_back(b.id);
    return ids;
  };
  return source;
}

Study studyFromJson(const Json& document, const std::filesystem::path& folder, const SceneSource& source) {
  if (!document.is_object()) throw InputError("(document)", jsonSnippet(document), "a study must be a JSON object");
  std::vector<FieldError> errors;
  Study study;
  study.folder = std::filesystem::absolute(folder).lexically_normal();
  study.document = document;
  const auto format = document.find("format");
  // The study.json that `study run` writes into its folder is the record of a study, not a study: name the file
  // it was run from instead of listing every field that a study file does not have.
  if (format != document.end() && *format == kStudyRunFormat) {
    const std::string from = document.value("study_file", std::string());
    throw InputError("format", jsonSnippet(*format),
                     "is a study folder's record (the study.json that `maris-cli study run` writes), not a study file" +
                         (from.empty() ? std::string() : "; the study was run from " + echoText(from)) +
                         "; `maris-cli study collect DIR` collects that folder again");
  }
  if (format == document.end())
    errors.push_back({"format", "", std::string("is missing; expected \"") + kStudyFormat + "\""});
  else if (!format->is_string() || format->get<std::string>() != kStudyFormat)
    errors.push_back({"format", jsonSnippet(*format), std::string("must be \"") + kStudyFormat + "\""});
  readText(document, "name", study.name, errors);
  readText(document, "description", study.description, errors);
  for (auto it = document.begin(); it != document.end(); ++it) {
    if (std::find(kFields.begin(), kFields.end(), it.key()) != kFields.end()) continue;
    const auto guess = didYouMean(it.key(), kFields);
    errors.push_back({it.key(), jsonSnippet(it.value()),
                      "unknown field" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?")});
  }
  if (const auto it = document.find("results"); it != document.end()) readResults(*it, study, errors);

  std::vector<std::string> designs;
  for (const auto& d : kDesigns)
    if (document.contains(d)) designs.push_back(d);
  if (designs.empty())
    errors.push_back({"grid", "", "is missing: a study needs one design, \"grid\", \"table\" or \"latin_hypercube\""});
  else if (designs.size() > 1)
    errors.push_back({designs[1], "", "cannot be combined with \"" + designs[0] + "\": a study has one design"});

  const auto base = document.find("base");
  const SceneDefinition* scene = nullptr;
  if (base == document.end()) {
    errors.push_back({"base", "", "is missing: a built-in scenario's name, a scenario file or a scenario object"});
  } else if (readBase(*base, source, study, errors)) {
    scene = source.scene(study.base.scene);
    if (!scene && !findScene(study.base.scene)) {
      try {
        requireScene(study.base.scene);  // the catalog's message: the scenes there are
      } catch (const InputError& e) {
        prefixErrors(e.errors(), "base.", errors);
      }
    } else if (!scene) {
      errors.push_back({"base.scene", jsonSnippet(Json(study.base.scene)), "is not a scene of this program"});
    }
    study.scene = scene;
  }
  if (scene) {
    study.notes = upgradeParameters(*scene, study.base.parameters);
    if (study.base_origin == "inline") resolveDataPaths(scene->schema, study.base.parameters, study.folder);
    if (const auto it = document.find("set"); it != document.end()) applySet(*it, *scene, study, errors);
    resolveDataPaths(scene->schema, study.base.parameters, study.folder);  // paths given in "set"
    if (const auto it = document.find("weighted_sum"); it != document.end())
      readWeightedSum(*it, designs.size() == 1 && designs[0] == "table", study, errors);
    if (designs.size() == 1) {
      const Json& design = document.at(designs[0]);
      if (designs[0] == "grid") detail::readGrid(design, *scene, study, errors);
      if (designs[0] == "table") detail::readTable(design, *scene, study, errors);
      if (designs[0] == "latin_hypercube") detail::readLatinHypercube(design, *scene, study, errors);
    }
  }
  if (!errors.empty()) throw InputError(std::move(errors));
  caseCount(study);  // refuses a study beyond the case limit before anything is expanded
  return study;
}

Study loadStudyFile(const std::filesystem::path& file, const SceneSource& source) {
  const std::string text = readInputFile(file, file.string(), InputLimits::kScenarioFileBytes);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(file.string(), "", "is empty; expected a JSON study document");
  const Json document = parseJsonLimited(text, file.string());
  return studyFromJson(document, std::filesystem::absolute(file).parent_path(), source);
}

}  // namespace maris::study
