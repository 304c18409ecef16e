// A study's output folder, shared by `study run`, the Slurm array tasks and `study collect`:
//
//   DIR/study.json               the study as run: its document, parameters, every case's values, versions,
//                                timings and (after collecting) every case's status
//   DIR/study.csv                one row per case (study_collect.hpp)
//   DIR/cases/0001.json          the case's scenario (written before anything runs)
//   DIR/cases/0001/              the case's run folder, exactly what `maris-cli run` writes; complete when it
//                                holds a summary.json that parses as a JSON object (a run folder appears whole
//                                or not at all; a power loss before the study synced it can leave it empty)
//   DIR/cases/0001.log           the case run's messages (stderr)
//   DIR/cases/0001.outcome.json  how the case's last attempt ended (status, exit code, message, wall time)
//   DIR/plots/*.png              each collected result against each varied parameter
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "study/study.hpp"

namespace maris::study {

inline constexpr const char* kStudyRunFormat = "maris-study-run/1";

// An output folder that cannot take the study (another study in it; --resume of a study that changed).
class StudyFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StudyFolder {
  std::filesystem::path root;
  std::filesystem::path manifest() const { return root / "study.json"; }
  std::filesystem::path csv() const { return root / "study.csv"; }
  std::filesystem::path cases() const { return root / "cases"; }
  std::filesystem::path plots() const { return root / "plots"; }
  std::filesystem::path caseScenario(const std::string& id) const { return cases() / (id + ".json"); }
  std::filesystem::path caseRun(const std::string& id) const { return cases() / id; }
  std::filesystem::path caseLog(const std::string& id) const { return cases() / (id + ".log"); }
  std::filesystem::path caseOutcome(const std::string& id) const { return cases() / (id + ".outcome.json"); }
  // The case's summary.json when the case is complete, else nullopt (no folder, no summary.json, or one
  // that does not parse as a JSON object: torn by a crash before its data reached the disk).
  std::optional<Json> caseSummary(const std::string& id) const;
  bool caseComplete(const std::string& id) const { return caseSummary(id).has_value(); }
};

enum class CaseStatus { Ok, Failed, Timeout, Missing };
const char* toString(CaseStatus status);  // "ok", "failed", "timeout", "missing"

// How a case's last attempt ended.
struct CaseOutcome {
  std::string id;
  CaseStatus status = CaseStatus::Missing;
  int exit_code = 0;        // the run's exit code (128 + signal when a signal ended it)
  std::string message;      // why it failed, from the run's messages
  double wall_s = 0.0;      // [s] from start to end of the case's process
  std::string started_at;   // UTC, ISO 8601
};
// `sync` Later: the study runner makes a batch of outcomes durable with one syncfs (study_runner.hpp).
void writeCaseOutcome(const StudyFolder& folder, const CaseOutcome& outcome, FileSync sync = FileSync::Now);
std::optional<CaseOutcome> readCaseOutcome(const StudyFolder& folder, const std::string& id);

// What study.json records of the study; read back by `study collect` and the array tasks.
struct StudyManifest {
  Json json;                                  // the whole document (timings are added to it)
  std::string scene;
  std::vector<StudyParameter> parameters;
  std::vector<std::string> results;           // requested scalars (empty: all)
  std::vector<std::string> ids;               // every case, in order
  std::vector<std::vector<Json>> values;      // per case, one value per parameter
  std::string weight_column;                  // a table study's "weighted_sum": the weights' column, or empty
  std::vector<double> weights;                // per case (when weight_column is set)
  std::vector<std::string> weighted_results;  // the scalars to sum, weighted
};

Json manifestJson(const Study& study, const std::vector<StudyCase>& cases, const std::filesystem::path& study_file);
// Throws InputError when DIR holds no study (no readable study.json of this format).
StudyManifest readManifest(const StudyFolder& folder);

// Writes every case's scenario and study.json into a new or emptied folder. With `resume`, DIR must hold
// the same study: each case file is compared with the one expanded now (a changed study is refused with
// StudyFolderError, naming the first differing case), and only missing files are written.
void prepareStudyFolder(const StudyFolder& folder, const Study& study, const std::vector<StudyCase>& cases,
                        const std::filesystem::path& study_file, bool resume);

// Why `dir` cannot take a new study (a file, a non-empty folder that is not a study, a study without
// --force or --resume), or nullopt. `force` allows replacing an earlier study's folder.
std::optional<std::string> studyFolderProblem(const std::filesystem::path& dir, bool resume, bool force);

// The lines of a run's messages that say why it failed (without progress lines), at most `max_chars`.
std::string failureMessage(const std::string& log, std::size_t max_chars = 400);

}  // namespace maris::study
