// Shared by the study commands (cli_study.cpp, cli_study_submit.cpp): preparing a study folder,
// locking it, collecting and reporting.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli_study.hpp"
#include "study/study_folder.hpp"

namespace CLI {
class App;
}

namespace maris::cli {

// An output folder the command will not write (exit code 1, like a refused run folder).
class StudyFolderRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An exclusive lock on DIR/.study.lock while a command prepares, runs or collects the study in DIR: a
// second `study run` or `collect` of the same folder is refused. (The Slurm array tasks take no such
// lock: each case's run folder has its own.)
class FolderLock {
 public:
  FolderLock(const std::filesystem::path& dir, const std::string& command);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

struct PreparedStudy {
  study::StudyFolder folder;
  std::string name;
  std::unique_ptr<FolderLock> lock;
};

// Loads the study, expands and checks every case (throws InputError listing every bad case, before anything
// is written), checks and locks the output folder (throws StudyFolderRefused), then writes the case files
// and study.json (with options.resume: checks that DIR holds the same study and removes old versions'
// leftovers; with options.force: removes the earlier study's files first).
PreparedStudy prepareStudy(const StudyOptions& options, const std::string& out, const std::string& command);

// Removes the staging folders (`.NNNN.partial-PID`, `.NNNN.old-PID`) that killed case runs of Maris 0.5 and
// earlier left in DIR/cases, each under its case's lock, with one listing of the folder (a case of this version
// does not look for them: `run --study-case`). Called by `study run --resume`, `submit --resume` and `collect`.
void removeOldVersionLeftovers(const study::StudyFolder& folder);

// Collects DIR into study.csv and study.json, draws the plots unless `no_plots`, prints the tally (and the
// failed and missing cases); returns 0 when every case is complete, else 3.
int collectAndReport(const study::StudyFolder& folder, study::StudyManifest& manifest, bool no_plots, int argc,
                     char** argv);

void addSubmitOptions(CLI::App& submit, StudyOptions& options);
int cmdSubmit(const StudyOptions& options);

// Indents every line after the first of a multi-line message by two spaces.
std::string indentLines(std::string text);

}  // namespace maris::cli
