// Helpers of the `maris-cli study` tests (test_cli_study*.cpp): files, a study started in the background,
// and the identity of each complete case (to tell a case that ran again from one that was kept).
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/schema.hpp"
#include "source_tree.hpp"

extern char** environ;

namespace maris::test {

inline std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

inline bool contains(const std::string& text, const std::string& piece) { return text.find(piece) != std::string::npos; }

// Starts maris-cli in the background (stdout and stderr to out.txt and err.txt in `dir`). With `own_group`
// it leads a process group of its own, which then holds its case processes too (kill(-pid, ...) ends all).
inline pid_t startCli(const std::vector<std::string>& args, const std::filesystem::path& dir, bool own_group = false) {
  std::vector<std::string> all = {maris::test::cliPath()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, (dir / "out.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, (dir / "err.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  if (own_group) {
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  }
  pid_t pid = 0;
  ::posix_spawn(&pid, all.front().c_str(), &files, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attributes);
  return pid;
}

// Every case folder under `cases` with a readable summary.json: its inode and start time, which change
// when the case runs again.
inline std::map<std::string, std::pair<ino_t, std::string>> completeCases(const std::filesystem::path& cases) {
  std::map<std::string, std::pair<ino_t, std::string>> complete;
  if (!std::filesystem::exists(cases)) return complete;
  for (const auto& e : std::filesystem::directory_iterator(cases)) {
    struct stat st {};
    if (e.path().filename().string().front() == '.') continue;  // a run's staging folder, not a case folder
    if (!e.is_directory() || ::stat((e.path() / "summary.json").c_str(), &st) != 0) continue;
    const Json summary = Json::parse(slurp(e.path() / "summary.json"), nullptr, false);
    if (summary.is_object()) complete[e.path().filename().string()] = {st.st_ino, summary.value("started_at", "")};
  }
  return complete;
}

}  // namespace maris::test
