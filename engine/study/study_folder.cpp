// The files of a study's output folder: the case scenarios, the manifest, each case's outcome.
#include "study/study_folder.hpp"

#include <system_error>

#include "core/input_limits.hpp"
#include "core/run_output.hpp"
#include "core/version.hpp"

namespace maris::study {

namespace {

ParamKind kindFromText(const std::string& text) {
  for (auto kind : {ParamKind::Real, ParamKind::Integer, ParamKind::Boolean, ParamKind::Choice, ParamKind::Text,
                    ParamKind::RealList, ParamKind::Table})
    if (text == toString(kind)) return kind;
  return ParamKind::Text;
}

CaseStatus statusFromText(const std::string& text) {
  for (auto s : {CaseStatus::Ok, CaseStatus::Failed, CaseStatus::Timeout})
    if (text == toString(s)) return s;
  return CaseStatus::Missing;
}

Json readJsonFile(const std::filesystem::path& file) {
  return parseJsonLimited(readInputFile(file, file.string(), InputLimits::kDataFileBytes), file.string());
}

// True when `file` is missing or empty.
bool caseFileEmpty(const std::filesystem::path& file) {
  std::error_code error;
  const auto size = std::filesystem::file_size(file, error);
  return error || size == 0;
}

}  // namespace

std::optional<Json> StudyFolder::caseSummary(const std::string& id) const {
  const auto summary = caseRun(id) / "summary.json";
  std::error_code error;
  if (!std::filesystem::is_regular_file(summary, error)) return std::nullopt;  // the usual case: not run yet
  try {
    Json j = parseJsonLimited(readInputFile(summary, summary.string(), InputLimits::kScenarioFileBytes),
                              summary.string());
    if (j.is_object()) return j;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

const char* toString(CaseStatus status) {
  switch (status) {
    case CaseStatus::Ok: return "ok";
    case CaseStatus::Failed: return "failed";
    case CaseStatus::Timeout: return "timeout";
    case CaseStatus::Missing: return "missing";
  }
  return "missing";
}

void writeCaseOutcome(const StudyFolder& folder, const CaseOutcome& outcome, FileSync sync) {
  const Json j = {{"case", outcome.id},          {"status", toString(outcome.status)},
                  {"exit_code", outcome.exit_code}, {"message", outcome.message},
                  {"wall_s", outcome.wall_s},    {"started_at", outcome.started_at}};
  writeFileAtomic(folder.caseOutcome(outcome.id), j.dump(2) + "\n", sync);
}

std::optional<CaseOutcome> readCaseOutcome(const StudyFolder& folder, const std::string& id) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(folder.caseOutcome(id), error)) return std::nullopt;
  try {
    const Json j = readJsonFile(folder.caseOutcome(id));
    CaseOutcome o;
    o.id = id;
    o.status = statusFromText(j.value("status", ""));
    o.exit_code = j.value("exit_code", 0);
    o.message = j.value("message", "");
    o.wall_s = j.value("wall_s", 0.0);
    o.started_at = j.value("started_at", "");
    return o;
  } catch (const std::exception&) {
    return std::nullopt;  // a torn or foreign file: the case counts as not run
  }
}

Json manifestJson(const Study& study, const std::vector<StudyCase>& cases, const std::filesystem::path& study_file) {
  Json parameters = Json::array();
  for (const auto& p : study.parameters)
    parameters.push_back({{"path", p.path}, {"unit", p.unit}, {"kind", toString(p.kind)}, {"label", p.label}});
  Json list = Json::array();
  const bool weighted = !study.weight_column.empty() && study.weights.size() == cases.size();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    list.push_back({{"id", cases[i].id}, {"values", cases[i].values}});
    if (weighted) list.back()["weight"] = study.weights[i];
  }
  Json manifest = {{"format", kStudyRunFormat},
          {"study_file", std::filesystem::absolute(study_file).lexically_normal().string()},
          {"name", study.name},
          {"description", study.description},
          {"scene", study.base.scene},
          {"base", study.base_origin},
          {"design", toString(study.kind)},
          {"parameters", parameters},
          {"results", study.results},
          {"case_count", cases.size()},
          {"cases", list},
          {"study", study.document},
          {"maris_version", projectVersion()},
          {"commit", commitId()},
          {"prepared_at", isoUtc(std::chrono::system_clock::now())},
          {"runs", Json::array()}};
  if (weighted) manifest["weighted_sum"] = {{"weight", study.weight_column}, {"results", study.weighted_results}};
  return manifest;
}

StudyManifest readManifest(const StudyFolder& folder) {
  const std::string where = folder.manifest().string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(folder.manifest(), error))
    throw InputError(where, "", "is missing: " + folder.root.string() + " holds no study (see `maris-cli study run`)");
  StudyManifest m;
  m.json = readJsonFile(folder.manifest());
  if (!m.json.is_object() || m.json.value("format", "") != kStudyRunFormat)
    throw InputError(where, "", std::string("is not a study folder's study.json (format \"") + kStudyRunFormat + "\")");
  try {
    m.scene = m.json.at("scene").get<std::string>();
    // study.json of Maris 0.9.0 and earlier records no labels: this program's schema of the scene gives them.
    const SceneDefinition* scene = catalogSource().scene(m.scene);
    for (const auto& p : m.json.at("parameters")) {
      m.parameters.push_back({p.at("path").get<std::string>(), p.at("unit").get<std::string>(),
                              kindFromText(p.at("kind").get<std::string>()), p.value("label", std::string())});
      if (m.parameters.back().label.empty() && scene)
        m.parameters.back().label = studyParameterLabel(scene->schema, m.parameters.back().path);
    }
    m.results = m.json.at("results").get<std::vector<std::string>>();
    if (const auto sum = m.json.find("weighted_sum"); sum != m.json.end()) {
      m.weight_column = sum->at("weight").get<std::string>();
      m.weighted_results = sum->at("results").get<std::vector<std::string>>();
    }
    for (const auto& c : m.json.at("cases")) {
      if (!m.weight_column.empty()) m.weights.push_back(c.at("weight").get<double>());
      m.ids.push_back(c.at("id").get<std::string>());
      m.values.push_back(c.at("values").get<std::vector<Json>>());
      if (m.values.back().size() != m.parameters.size() || m.ids.back().find('/') != std::string::npos)
        throw InputError(where, "", "case " + echoText(m.ids.back()) + " does not match the study's parameters");
    }
  } catch (const Json::exception& e) {
    throw InputError(where, "", std::string("is damaged: ") + e.what());
  }
  return m;
}

std::optional<std::string> studyFolderProblem(const std::filesystem::path& dir, bool resume, bool force) {
  std::error_code error;
  const auto status = std::filesystem::status(dir, error);
  if (!std::filesystem::exists(status)) return std::nullopt;
  if (!std::filesystem::is_directory(status)) return "is not a folder";
  if (std::filesystem::is_empty(dir, error)) return std::nullopt;
  if (!std::filesystem::exists(StudyFolder{dir}.manifest(), error))
    return "is not empty and holds no study (its files are never replaced); choose another --out";
  if (!resume && !force) return "holds an earlier study; --resume finishes it, --force starts it over";
  return std::nullopt;
}

void prepareStudyFolder(const StudyFolder& folder, const Study& study, const std::vector<StudyCase>& cases,
                        const std::filesystem::path& study_file, bool resume) {
  std::filesystem::create_directories(folder.cases());
  Json manifest = manifestJson(study, cases, study_file);
  if (resume && std::filesystem::exists(folder.manifest())) {
    const StudyManifest earlier = readManifest(folder);
    const auto refuse = [&](const std::string& why) {
      throw StudyFolderError("--resume: " + folder.root.string() + " holds a different study (" + why +
                             "); use another --out, or --force to start over");
    };
    if (earlier.ids.size() != cases.size())
      refuse(std::to_string(earlier.ids.size()) + " cases there, " + std::to_string(cases.size()) + " now");
    for (const auto& c : cases) {
      std::error_code error;
      if (caseFileEmpty(folder.caseScenario(c.id))) continue;  // not there, or not yet durable at a crash
      if (readInputFile(folder.caseScenario(c.id), folder.caseScenario(c.id).string(),
                        InputLimits::kScenarioFileBytes) != scenarioToText(c.scenario))
        refuse("case " + c.id + " differs from " + folder.caseScenario(c.id).string());
    }
    manifest["prepared_at"] = earlier.json.value("prepared_at", manifest["prepared_at"]);
    manifest["runs"] = earlier.json.value("runs", Json::array());
  }
  // study.json first: a folder whose preparation was interrupted is a study that --resume completes.
  writeFileAtomic(folder.manifest(), manifest.dump(1) + "\n");
  // The case files are made durable by one flush after the last (10 000 fsyncs took seconds, before any
  // case ran); until then a crash can leave one empty, which --resume writes again.
  bool written = false;
  for (const auto& c : cases) {
    if (resume && !caseFileEmpty(folder.caseScenario(c.id))) continue;
    writeFileAtomic(folder.caseScenario(c.id), scenarioToText(c.scenario), FileSync::Later);
    written = true;
  }
  if (written) syncFileSystem(folder.cases());
}

std::string failureMessage(const std::string& log, std::size_t max_chars) {
  std::string message;
  std::size_t start = 0;
  while (start < log.size()) {
    auto end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    std::string line = log.substr(start, end - start);
    start = end + 1;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    line = line.substr(first);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.rfind("progress ", 0) == 0 || line.rfind("running ", 0) == 0 || line.rfind("note: ", 0) == 0 ||
        line.rfind("warning: ", 0) == 0)
      continue;
    message += (message.empty() ? "" : " ") + line;
  }
  return echoText(message, max_chars);
}

}  // namespace maris::study
