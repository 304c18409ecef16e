#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "cli_conventions.hpp"
#include "cli_study_internal.hpp"
#include "core/input_limits.hpp"
#include "core/run_folder.hpp"
#include "plot_writer.hpp"
#include "study/study_collect.hpp"

namespace maris::cli {

using namespace maris::study;

std::string indentLines(std::string text) {
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 3)) text.insert(at + 1, "  ");
  return text;
}

FolderLock::FolderLock(const std::filesystem::path& dir, const std::string& command) {
  const auto file = dir / ".study.lock";
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw StudyFolderRefused(dir.string() + ": cannot be written (" + std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw StudyFolderRefused(dir.string() + " is in use by another " + command + " (a lock on " + file.string() + ")");
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

PreparedStudy prepareStudy(const StudyOptions& options, const std::string& out, const std::string& command) {
  const Study study = loadStudyFile(options.study_file);
  for (const auto& note : study.notes) std::fprintf(stderr, "note: base: %s\n", note.c_str());
  const auto cases = expandStudy(study);
  if (auto errors = caseErrors(study, cases, options.allow_large); !errors.empty()) throw InputError(errors);

  PreparedStudy prepared;
  prepared.folder.root = std::filesystem::absolute(out).lexically_normal();
  prepared.name = study.name.empty() ? std::filesystem::path(options.study_file).stem().string() : study.name;
  const StudyFolder& folder = prepared.folder;
  if (auto problem = studyFolderProblem(folder.root, options.resume, options.force))
    throw StudyFolderRefused("--out " + folder.root.string() + " " + *problem);
  std::error_code error;
  std::filesystem::create_directories(folder.root, error);
  if (error) throw StudyFolderRefused("--out " + folder.root.string() + " cannot be created (" + error.message() + ")");
  prepared.lock = std::make_unique<FolderLock>(folder.root, command);
  if (options.force && !options.resume) {
    for (const auto& p : {folder.cases(), folder.plots(), folder.csv(), folder.root / "slurm", folder.manifest()})
      std::filesystem::remove_all(p);
  }
  prepareStudyFolder(folder, study, cases, options.study_file, options.resume);
  if (options.resume) removeOldVersionLeftovers(folder);
  return prepared;
}

void removeOldVersionLeftovers(const StudyFolder& folder) {
  if (const std::size_t removed = maris::removeOldVersionLeftovers(folder.cases()))
    std::fprintf(stderr, "note: removed %zu staging folder%s that killed runs of an earlier maris version left in %s\n",
                 removed, removed == 1 ? "" : "s", folder.cases().c_str());
}

int collectAndReport(const StudyFolder& folder, StudyManifest& manifest, bool no_plots, int argc, char** argv) {
  const CollectedStudy collected = collectStudy(folder, manifest);
  writeCollected(folder, manifest, collected);
  for (const auto& w : collected.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  std::size_t pngs = 0;
  if (!no_plots) {
    std::error_code error;
    std::filesystem::create_directories(folder.plots(), error);
    for (const auto& entry : std::filesystem::directory_iterator(folder.plots(), error))
      if (entry.path().extension() == ".png") std::filesystem::remove(entry.path(), error);  // an earlier collection's
    pngs = writeStudyPngs(folder.plots(), collected, manifest, argc, argv).size();
  }
  std::vector<std::size_t> missing;
  std::size_t listed = 0;
  for (std::size_t i = 0; i < collected.cases.size(); ++i) {
    const auto& c = collected.cases[i];
    if (c.status == CaseStatus::Missing) missing.push_back(i);
    if (c.status != CaseStatus::Failed && c.status != CaseStatus::Timeout) continue;
    if (++listed <= kReportedErrorLimit)
      std::fprintf(stderr, "case %s %s (exit code %d): %s\n", c.id.c_str(), toString(c.status), c.outcome.exit_code,
                   c.outcome.message.c_str());
  }
  if (listed > kReportedErrorLimit) std::fprintf(stderr, "... and %zu more failed cases (study.json lists them)\n",
                                                 listed - kReportedErrorLimit);
  if (!missing.empty())
    std::fprintf(stderr, "not run yet: %s\n", echoText(caseRanges(missing, collected.cases.size()), 400).c_str());
  std::printf("%zu cases: %zu ok, %zu failed, %zu timed out, %zu not run\n", collected.cases.size(),
              collected.count(CaseStatus::Ok), collected.count(CaseStatus::Failed),
              collected.count(CaseStatus::Timeout), missing.size());
  for (const auto& sum : collected.weighted_sums) {
    std::string ids;
    for (const auto& id : sum.missing) ids += (ids.empty() ? "" : ", ") + id;
    if (sum.value)
      std::printf("weighted sum of %s over %s: %.6g %s (weights add up to %.6g)\n", sum.result.c_str(),
                  manifest.weight_column.c_str(), *sum.value, sum.unit.c_str(), sum.weight_total);
    else
      std::printf("weighted sum of %s over %s: not yet; %s %s %s weight but no value\n", sum.result.c_str(),
                  manifest.weight_column.c_str(), sum.missing.size() == 1 ? "case" : "cases", echoText(ids, 400).c_str(),
                  sum.missing.size() == 1 ? "has" : "have");
  }
  std::printf("study.csv written to %s (%zu results per case)%s\n", folder.csv().c_str(),
              collected.result_names.size(),
              pngs ? (", PNG plots: " + std::to_string(pngs) + " in " + folder.plots().string()).c_str() : "");
  return collected.count(CaseStatus::Ok) == collected.cases.size() ? kExitOk : kExitSolverFailure;
}

}  // namespace maris::cli
