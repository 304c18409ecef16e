// StudySession: the calls into the engine's study model (study file, expansion and validation of the
// cases, study.csv). The panel's grid becomes the same study document `maris-cli study run` reads.
#include <algorithm>

#include "core/errors.hpp"
#include "core/run_output.hpp"
#include "scene_library.hpp"
#include "core/input_limits.hpp"
#include "study/study_collect.hpp"
#include "study/study_folder.hpp"
#include "study/study_session.hpp"
#include "study/study_session_impl.hpp"

namespace maris::ui {

namespace {

bool logSpacing(const Json& entry) { return entry.is_object() && entry.value("spacing", "") == "log"; }

// A grid entry as the panel edits it (an explicit list shows as its first and last value and count).
SweepRange toSweep(const std::string& path, const std::vector<Json>& values, const Json& entry) {
  SweepRange r;
  r.path = path;
  if (entry.is_object()) {
    r.from = entry.value("from", 0.0);
    r.to = entry.value("to", 0.0);
    r.count = entry.value("count", 0);
    r.log = logSpacing(entry);
  } else if (!values.empty() && values.front().is_number() && values.back().is_number()) {
    r.from = values.front().get<double>();
    r.to = values.back().get<double>();
    r.count = static_cast<int>(values.size());
  }
  return r;
}

// The study's scenes: the GUI's library (which may hold scenes beside the catalog's).
study::SceneSource librarySource(const SceneLibrary& library) {
  study::SceneSource source;
  source.scene = [&library](const std::string& name) { return library.findScene(name); };
  source.builtin = [&library](const std::string& id) -> const Scenario* {
    const BuiltinScenario* found = library.findExample(id);
    return found ? &found->scenario : nullptr;
  };
  source.builtin_ids = [&library] {
    std::vector<std::string> ids;
    for (const auto& example : library.examples) ids.push_back(example.id);
    return ids;
  };
  return source;
}

// One scene, for a study over the open scenario (kept inline, so no built-in is looked up).
study::SceneSource oneScene(const SceneDefinition& scene) {
  study::SceneSource source;
  source.scene = [&scene](const std::string& name) { return name == scene.name ? &scene : nullptr; };
  source.builtin = [](const std::string&) -> const Scenario* { return nullptr; };
  source.builtin_ids = [] { return std::vector<std::string>(); };
  return source;
}

std::vector<bool> logParameters(const study::Study& s) {
  std::vector<bool> log;
  for (const auto& parameter : s.parameters) log.push_back(study::logSpaced(s.document, parameter.path));
  return log;
}

}  // namespace

void StudySession::define(const SceneDefinition& scene, const Scenario& base, std::vector<SweepRange> grid) {
  // In the order of their paths, as a study file reads back (JSON objects keep no order).
  std::sort(grid.begin(), grid.end(), [](const SweepRange& a, const SweepRange& b) { return a.path < b.path; });
  Json ranges = Json::object();
  for (const SweepRange& r : grid)
    ranges[r.path] = {{"from", r.from}, {"to", r.to}, {"count", r.count}, {"spacing", r.log ? "log" : "linear"}};
  const Json document = {{"format", study::kStudyFormat},
                         {"name", base.name + " study"},
                         {"base", scenarioToJson(base)},
                         {"grid", ranges}};
  adopt(scene, base, document, std::filesystem::current_path(), std::move(grid));
}

void StudySession::defineTable(const SceneDefinition& scene, const Scenario& base, const QString& csv_file,
                               const std::string& weight_column, const std::vector<std::string>& weighted_results) {
  const std::filesystem::path table = std::filesystem::absolute(csv_file.toStdString());
  Json document = {{"format", study::kStudyFormat},
                   {"name", base.name + " load cases"},
                   {"base", scenarioToJson(base)},
                   {"table", table.string()}};
  if (!weight_column.empty()) document["weighted_sum"] = {{"weight", weight_column}, {"results", weighted_results}};
  adopt(scene, base, document, table.parent_path(), {});
}

bool StudySession::isGrid() const { return !impl_ || impl_->study.kind == study::DesignKind::Grid; }

bool StudySession::isTable() const { return impl_ && impl_->study.kind == study::DesignKind::Table; }

std::string StudySession::weightColumn() const { return impl_ ? impl_->study.weight_column : std::string(); }

std::vector<std::string> StudySession::weightedResults() const {
  return impl_ ? impl_->study.weighted_results : std::vector<std::string>();
}

std::vector<std::string> StudySession::nonParameterColumns(const SceneDefinition& scene, const Json& parameters,
                                                           const QString& csv_file) {
  // A column close to a parameter's path is a misspelt parameter, not a weight: the engine refuses it with a guess.
  std::vector<std::string> paths;
  for (const auto& field : scene.schema.fields) paths.push_back(field.path);
  std::vector<std::string> columns;
  for (const std::string& name : study::tableColumns(std::filesystem::absolute(csv_file.toStdString())))
    if (!name.empty() && !study::findStudyParameter(scene, parameters, name) && didYouMean(name, paths).empty())
      columns.push_back(name);
  return columns;
}

std::vector<std::string> StudySession::weightCandidates() const {
  if (!isTable() || !scene_) return {};
  try {
    return nonParameterColumns(*scene_, impl_->study.base.parameters, QString::fromStdString(impl_->study.table_file.string()));
  } catch (const std::exception&) {
    return {};  // the table is gone or changed since: setWeightedSum says why
  }
}

void StudySession::setWeightedSum(const std::string& column, const std::vector<std::string>& results) {
  if (!isTable() || !scene_) throw std::runtime_error("a weighted sum needs a table study (the weights are a column of its table)");
  // The study as it runs, as save() writes it: the base in place (a base file or "set" was read relative to
  // the study file's folder), the table by its absolute path.
  Json document = impl_->study.document;
  document["base"] = scenarioToJson(impl_->study.base);
  document.erase("set");
  document["table"] = impl_->study.table_file.string();
  if (column.empty())
    document.erase("weighted_sum");
  else
    document["weighted_sum"] = {{"weight", column}, {"results", results}};
  auto impl = std::make_shared<Impl>(*impl_);
  impl->study = study::studyFromJson(document, impl_->study.folder, oneScene(*scene_));  // throws before anything changes
  impl->log = logParameters(impl->study);
  const bool same_cases = impl->study.rows == impl_->study.rows && impl->study.parameters.size() == impl_->study.parameters.size();
  if (!same_cases) {
    impl->cases.clear();
    impl->value_digits.clear();
    outcomes_.clear();
  }
  impl_ = std::move(impl);
}

study::CollectedStudy StudySession::collected(std::vector<study::CaseScalars>* scalars_out) const {
  std::vector<study::CollectedCase> cases;
  std::vector<study::CaseScalars> scalars;
  for (std::size_t i = 0; impl_ && i < impl_->cases.size() && i < outcomes_.size(); ++i) {
    study::CollectedCase c;
    c.id = impl_->cases[i].id;
    c.values = impl_->cases[i].values;
    const CaseOutcome& o = outcomes_[i];
    c.status = o.status == Status::Finished && o.results ? study::CaseStatus::Ok
               : o.status == Status::Failed               ? study::CaseStatus::Failed
                                                          : study::CaseStatus::Missing;
    study::CaseScalars values;
    if (o.results)
      for (const Scalar& s : o.results->scalars) values[s.name] = {s.value, s.unit.empty() ? "-" : s.unit};
    cases.push_back(std::move(c));
    scalars.push_back(std::move(values));
  }
  auto result = study::collectScalars(impl_ ? impl_->study.parameters : std::vector<study::StudyParameter>(),
                                      impl_ ? impl_->study.results : std::vector<std::string>(), std::move(cases), scalars);
  if (scalars_out) *scalars_out = std::move(scalars);
  return result;
}

std::vector<study::WeightedSum> StudySession::weightedSums() const {
  if (!impl_ || impl_->study.weight_column.empty() || impl_->cases.empty()) return {};
  std::vector<study::CaseScalars> scalars;
  const study::CollectedStudy cases = collected(&scalars);
  return study::weightedSums(impl_->study.weighted_results, impl_->study.weights, cases.cases, scalars);
}

void StudySession::defineLatinHypercube(const SceneDefinition& scene, const Scenario& base,
                                        const LatinHypercubeDesign& design) {
  Json bounds = Json::object();
  for (const SweepRange& r : design.ranges) bounds[r.path] = Json::array({r.from, r.to});
  const Json document = {{"format", study::kStudyFormat},
                         {"name", base.name + " Latin hypercube"},
                         {"base", scenarioToJson(base)},
                         {"latin_hypercube", {{"count", design.samples}, {"seed", design.seed}, {"bounds", bounds}}}};
  adopt(scene, base, document, std::filesystem::current_path(), {});
}

void StudySession::adopt(const SceneDefinition& scene, const Scenario& base, const Json& document,
                         const std::filesystem::path& folder, std::vector<SweepRange> grid) {
  auto owned = std::make_shared<const SceneDefinition>(scene);
  auto impl = std::make_shared<Impl>();
  impl->study = study::studyFromJson(document, folder, oneScene(*owned));  // throws before anything changes
  impl->log = logParameters(impl->study);
  scene_ = std::move(owned);
  base_ = base;
  grid_ = std::move(grid);
  impl_ = std::move(impl);
  outcomes_.clear();
  folder_.clear();
}

std::vector<std::string> StudySession::parameterPaths() const {
  std::vector<std::string> paths;
  if (impl_)
    for (const auto& p : impl_->study.parameters) paths.push_back(p.path);
  return paths;
}

std::vector<std::string> StudySession::parameterLabels() const {
  std::vector<std::string> labels;
  if (impl_)
    for (const auto& p : impl_->study.parameters) labels.push_back(study::displayLabel(p));
  return labels;
}

void StudySession::load(const QString& file, const SceneLibrary& library) {
  auto impl = std::make_shared<Impl>();
  impl->study = study::loadStudyFile(file.toStdString(), librarySource(library));
  const SceneDefinition* scene = library.findScene(impl->study.base.scene);
  if (!scene) throw InputError("base.scene", impl->study.base.scene, "is not a scene of this program");
  impl->log = logParameters(impl->study);
  std::vector<SweepRange> grid;
  if (impl->study.kind == study::DesignKind::Grid)
    for (std::size_t p = 0; p < impl->study.parameters.size(); ++p) {
      const std::string& path = impl->study.parameters[p].path;
      grid.push_back(toSweep(path, impl->study.grid[p], impl->study.document.at("grid").value(path, Json())));
    }
  scene_ = std::make_shared<const SceneDefinition>(*scene);
  impl->study.scene = scene_.get();  // the session's own copy, however long the library lives
  base_ = impl->study.base;
  grid_ = std::move(grid);
  impl_ = std::move(impl);
  outcomes_.clear();
  folder_.clear();
}

void StudySession::loadFolder(const QString& dir, const SceneLibrary& library) {
  const study::StudyFolder folder{std::filesystem::absolute(dir.toStdString()).lexically_normal()};
  const study::StudyManifest manifest = study::readManifest(folder);  // InputError when DIR holds no study
  const SceneDefinition* scene = library.findScene(manifest.scene);
  if (!scene) throw InputError("scene", manifest.scene, "is not a scene of this program");
  auto impl = std::make_shared<Impl>();
  study::Study& s = impl->study;
  s.document = manifest.json.value("study", Json::object());
  s.name = s.document.is_object() ? s.document.value("name", std::string()) : std::string();
  if (s.name.empty()) s.name = folder.root.filename().string();
  s.folder = folder.root;
  const std::string design = manifest.json.value("design", std::string("grid"));
  s.kind = design == "table"             ? study::DesignKind::Table
           : design == "latin_hypercube" ? study::DesignKind::LatinHypercube
                                         : study::DesignKind::Grid;
  s.parameters = manifest.parameters;
  for (auto& p : s.parameters)  // a folder whose study.json records no labels: the scene's schema has them
    if (p.label.empty()) p.label = study::studyParameterLabel(scene->schema, p.path);
  s.results = manifest.results;
  s.weight_column = manifest.weight_column;
  s.weights = manifest.weights;
  s.weighted_results = manifest.weighted_results;
  impl->log = logParameters(s);
  std::vector<CaseOutcome> outcomes;
  for (std::size_t i = 0; i < manifest.ids.size(); ++i) {
    const std::string& id = manifest.ids[i];
    const std::filesystem::path file = folder.caseScenario(id);
    study::StudyCase c;
    c.id = id;
    c.values = i < manifest.values.size() ? manifest.values[i] : std::vector<Json>();
    c.scenario = scenarioFromJson(parseJsonLimited(readInputFile(file, file.string(), InputLimits::kScenarioFileBytes), file.string()));
    impl->cases.push_back(std::move(c));
    CaseOutcome outcome;
    const auto record = study::readCaseOutcome(folder, id);
    if (record) outcome.wall_time_s = record->wall_s;
    if (const auto summary = folder.caseSummary(id)) {
      // The scalars as the run wrote them (labels and units for the plot's axes and the sums); a case's tables
      // are in its run folder.
      auto results = std::make_shared<Results>();
      if (const auto r = summary->find("results"); r != summary->end() && r->is_object())
        for (const auto& [name, value] : r->items())
          if (value.is_object() && value.contains("value") && value["value"].is_number())
            results->addScalar(name, value["value"].get<double>(), value.value("unit", std::string("-")),
                               value.value("description", std::string()), value.value("label", std::string()));
      outcome.status = Status::Finished;
      outcome.results = std::move(results);
    } else if (record && (record->status == study::CaseStatus::Failed || record->status == study::CaseStatus::Timeout)) {
      outcome.status = Status::Failed;
      outcome.error = QString::fromStdString(record->status == study::CaseStatus::Timeout ? "timed out: " + record->message
                                                                                          : record->message);
    }
    outcomes.push_back(std::move(outcome));
  }
  // The base as the plot and the dock name it: the study's name over the first case's scenario (the base itself
  // is not in the folder; the cases are).
  Scenario base = impl->cases.empty() ? Scenario() : impl->cases.front().scenario;
  base.name = s.name;
  base.scene = manifest.scene;
  s.base = base;
  s.scene = nullptr;
  scene_ = std::make_shared<const SceneDefinition>(*scene);
  s.scene = scene_.get();
  base_ = std::move(base);
  grid_.clear();
  impl_ = std::move(impl);
  outcomes_ = std::move(outcomes);
  folder_ = QString::fromStdString(folder.root.string());
}

void StudySession::save(const QString& file) const {
  if (!impl_) throw std::runtime_error("no study is defined");
  if (!folder_.isEmpty())
    throw std::runtime_error("this study was opened from its folder " + folder_.toStdString() +
                             "; its study file is the one it was run from (study.json names it as study_file)");
  Json document = impl_->study.document;
  // The base as it runs (a file or built-in name read relative to the old study file would not resolve
  // from another folder); a table is written with its absolute path for the same reason.
  document["base"] = scenarioToJson(impl_->study.base);
  document.erase("set");
  if (impl_->study.kind == study::DesignKind::Table) document["table"] = impl_->study.table_file.string();
  writeFileAtomic(file.toStdString(), document.dump(2) + "\n");
}

QString StudySession::kindName() const {
  if (!impl_) return QObject::tr("grid");
  switch (impl_->study.kind) {
    case study::DesignKind::Table: return QObject::tr("table");
    case study::DesignKind::LatinHypercube: return QObject::tr("latin hypercube");
    case study::DesignKind::Grid: break;
  }
  return QObject::tr("grid");
}

void StudySession::expand() {
  if (!impl_ || !scene_) throw std::runtime_error("no study is defined");
  impl_->cases.clear();
  impl_->value_digits.clear();
  outcomes_.clear();
  std::vector<study::StudyCase> cases = study::expandStudy(impl_->study);
  const std::vector<FieldError> errors = study::caseErrors(impl_->study, cases, false);
  if (!errors.empty()) throw InputError(errors);
  impl_->cases = std::move(cases);
  outcomes_.assign(impl_->cases.size(), CaseOutcome{});
}

void StudySession::writeCsv(const QString& file) const {
  if (!impl_ || impl_->cases.empty()) throw std::runtime_error("the study has no cases yet: run it first");
  writeFileAtomic(file.toStdString(), study::studyCsv(collected()));
}

}  // namespace maris::ui
