#include "core/run_folder.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/scenario.hpp"
#include "core/text_format.hpp"

namespace maris {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

[[noreturn]] void fail(const std::string& message) { throw RunFolderError(message); }

std::string megabytes(std::uintmax_t bytes) { return formatText("%.1f MB", static_cast<double>(bytes) / 1e6); }

// The staging and set-aside folders of `target`. Their names are fixed (no process id): only the holder of
// the lock writes them, so one that exists when the lock is taken was left by a killed run. Removing it by
// name costs the same in a folder of ten thousand runs as in an empty one (a study's cases folder).
fs::path stagingFolder(const fs::path& target) {
  return target.parent_path() / ("." + target.filename().string() + ".partial");
}
fs::path asideFolder(const fs::path& target) {
  return target.parent_path() / ("." + target.filename().string() + ".old");
}

fs::path lockFile(const fs::path& target) {
  return target.parent_path() / ("." + target.filename().string() + ".lock");
}

// The NAME of a staging or set-aside folder of Maris 0.5 and earlier (`.NAME.partial-PID`, `.NAME.old-PID`:
// a dot, a non-empty NAME, the suffix, a dash and only digits), or "" for any other file name.
std::string oldVersionLeftoverOwner(const std::string& entry) {
  const auto dash = entry.rfind('-');
  if (entry.empty() || entry.front() != '.' || dash == std::string::npos || dash + 1 == entry.size()) return "";
  if (entry.size() - dash - 1 > 10) return "";  // longer than any process id
  for (std::size_t i = dash + 1; i < entry.size(); ++i)
    if (entry[i] < '0' || entry[i] > '9') return "";
  const std::string stem = entry.substr(1, dash - 1);  // NAME.partial or NAME.old
  for (const std::string suffix : {".partial", ".old"}) {
    if (stem.size() > suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
      return stem.substr(0, stem.size() - suffix.size());
  }
  return "";
}

// Every old version's leftover in `parent` (one listing), with its owner's NAME.
std::vector<std::pair<fs::path, std::string>> oldVersionLeftovers(const fs::path& parent) {
  std::vector<std::pair<fs::path, std::string>> found;
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    std::string owner = oldVersionLeftoverOwner(it->path().filename().string());
    if (!owner.empty()) found.emplace_back(it->path(), std::move(owner));
  }
  return found;
}

// Removes the staging and set-aside folders that a killed run left next to `target` (called under the lock).
void removeStale(const fs::path& target, bool old_version_leftovers) {
  std::error_code ec;
  fs::remove_all(stagingFolder(target), ec);
  fs::remove_all(asideFolder(target), ec);
  if (!old_version_leftovers) return;
  for (const auto& [path, owner] : oldVersionLeftovers(target.parent_path()))
    if (owner == target.filename().string()) fs::remove_all(path, ec);
}

void syncDirectory(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Makes every file below `dir` durable (written unsynced: writeStagedFile, plot images) with one
// syncfs(2) of its file system: one flush of the device instead of one per file (each fsync of a freshly
// written file costs a journal commit and a device flush, ~4 ms here; a small run writes ten files).
void syncTree(const fs::path& dir) {
  try {
    syncFileSystem(dir);
  } catch (const std::runtime_error& e) {
    fail(e.what());
  }
}

}  // namespace

bool isRunFolder(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "summary.json", ec) || fs::exists(dir / "scenario.json", ec);
}

std::size_t removeOldVersionLeftovers(const fs::path& parent) {
  std::size_t removed = 0;
  for (const auto& [path, owner] : oldVersionLeftovers(parent)) {
    const fs::path lock = lockFile(parent / owner);
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {  // no run writes NAME now: the folder is a killed run's
      std::error_code ec;
      if (fs::remove_all(path, ec) > 0 && !ec) ++removed;
    }
    ::close(fd);  // releases the flock
  }
  return removed;
}

bool runFolderBusy(const fs::path& target) {
  fs::path normal = fs::absolute(target).lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();  // "out/" -> "out"
  const fs::path lock = lockFile(normal);
  const int fd = ::open(lock.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;  // never locked: no run has written the folder
  const bool busy = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return busy;
}

RunFolder::RunFolder(fs::path target, RunFolderOptions options) : options_(options) {
  if (target.empty()) fail("the output folder is empty: name a folder");
  std::error_code ec;
  target = fs::absolute(target, ec).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/" -> "out"
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == ".." || target == target.root_path())
    fail("the output folder " + quoted(target) + " must name a folder of its own");
  target_ = target;
  const fs::path parent = target.parent_path();

  fs::create_directories(parent, ec);
  if (ec) fail("cannot create the output folder's parent " + quoted(parent) + ": " + ec.message());
  if (!fs::is_directory(parent, ec)) fail(quoted(parent) + " is not a folder");

  // The lock is also the first write: a read-only or foreign parent fails here, before any solve.
  const fs::path lock = lockFile(target);
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) fail("cannot write in " + quoted(parent) + ": " + std::strerror(errno));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (err == EWOULDBLOCK)
      fail("another maris run is writing " + quoted(target) + " (it holds " + quoted(lock) +
           "); wait for it to finish or choose another output folder");
    fail("cannot lock " + quoted(lock) + ": " + std::strerror(err));
  }
  // From here the destructor must run on failure: release the lock through it.
  try {
    const auto status = fs::symlink_status(target, ec);
    if (fs::exists(status)) {
      if (!fs::is_directory(status))
        fail(quoted(target) + " exists and is not a folder; choose another output folder");
      const bool empty = fs::is_empty(target, ec);
      if (!empty && !isRunFolder(target))
        fail(quoted(target) + " holds files that are not a maris run; maris never replaces such a folder, "
             "choose another output folder");
      if (!empty && !options_.replace)
        fail(quoted(target) + " holds the results of another run; choose another output folder or replace "
             "them (maris-cli run --force)");
    }
    removeStale(target, options_.remove_old_version_leftovers);
    staging_ = stagingFolder(target);
    if (::mkdir(staging_.c_str(), 0755) != 0) {
      const int err = errno;
      staging_.clear();
      fail("cannot write in " + quoted(parent) + ": " + std::strerror(err));
    }
    const auto space = fs::space(parent, ec);
    if (!ec && space.available < options_.expected_bytes)
      fail("not enough free space for " + quoted(target) + ": the run writes about " +
           megabytes(options_.expected_bytes) + ", " + megabytes(space.available) + " are free");
  } catch (...) {
    release();
    throw;
  }
}

RunFolder::~RunFolder() { release(); }

void RunFolder::release() {
  std::error_code ec;
  if (!committed_ && !staging_.empty()) fs::remove_all(staging_, ec);
  staging_.clear();
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the flock
  lock_fd_ = -1;
}

void RunFolder::commit() {
  if (committed_ || staging_.empty()) fail("run folder " + quoted(target_) + " was already committed");
  if (options_.sync) syncTree(staging_);
  std::error_code ec;
  const bool exists = fs::exists(fs::symlink_status(target_, ec));
  if (!exists || fs::is_empty(target_, ec)) {
    // rename(2) replaces an empty folder atomically.
    if (::rename(staging_.c_str(), target_.c_str()) != 0)
      fail("cannot move the results into " + quoted(target_) + ": " + std::strerror(errno));
    committed_ = true;
  } else {
    if (!options_.replace || !isRunFolder(target_))
      fail(quoted(target_) + " was filled by someone else during the run; the results were not written");
    // Swap new and old in one step where the file system can; otherwise set the old one aside first.
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
      committed_ = true;
      fs::remove_all(staging_, ec);  // now the old run
    } else {
      const fs::path aside = asideFolder(target_);
      if (::rename(target_.c_str(), aside.c_str()) != 0)
        fail("cannot replace " + quoted(target_) + ": " + std::strerror(errno));
      if (::rename(staging_.c_str(), target_.c_str()) != 0) {
        const int err = errno;
        ::rename(aside.c_str(), target_.c_str());
        fail("cannot move the results into " + quoted(target_) + ": " + std::strerror(err));
      }
      committed_ = true;
      fs::remove_all(aside, ec);
    }
  }
  staging_.clear();
  if (options_.sync) syncDirectory(target_.parent_path());
}

}  // namespace maris
