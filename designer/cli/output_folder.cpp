#include "designer/cli/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "models/core/errors.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

// The pid a lock file names, or "" when it holds none.
std::string owner_of(int fd) {
  char buffer[32] = {};
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  std::string pid(buffer, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid;
}

}  // namespace

void CreatedFolders::create(const fs::path& folder) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = folder; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(folder, ec);
  if (ec) {
    made_.insert(made_.end(), missing.rbegin(), missing.rend());
    remove_empty();
    throw std::runtime_error("cannot create the folder " + folder.string() + ": " + ec.message());
  }
  if (!fs::is_directory(folder, ec))
    throw std::runtime_error("cannot use " + folder.string() + " as a folder: it is a file");
  made_.insert(made_.end(), missing.rbegin(), missing.rend());
}

void CreatedFolders::remove_empty() noexcept {
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) {
    std::error_code ec;
    if (!fs::is_empty(*it, ec) || ec) break;
    fs::remove(*it, ec);
  }
  made_.clear();
}

OutputFolder::OutputFolder(fs::path folder, const std::string& option) : folder_(std::move(folder)) {
  try {
    created_.create(folder_);
  } catch (const std::runtime_error& e) {
    throw InputError(option, "", e.what());
  }
  const fs::path lock = folder_ / kLockName;
  // The lock file may be removed by the run holding it just after this opened it: lock, then
  // check that the path still names the locked file, else start again.
  for (;;) {
    const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      const std::string reason = std::strerror(errno);
      created_.remove_empty();
      throw InputError(option, "", "cannot lock the output folder " + folder_.string() + ": " + reason);
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const std::string pid = owner_of(fd);
      ::close(fd);
      throw InputError(option, "",
                       "output folder " + folder_.string() + " in use by another feedflow run" +
                           (pid.empty() ? std::string() : " (pid " + pid + ")") +
                           "; wait for it to end or choose another folder with --out");
    }
    struct stat locked {};
    struct stat named {};
    if (::fstat(fd, &locked) == 0 && ::stat(lock.c_str(), &named) == 0 &&
        locked.st_dev == named.st_dev && locked.st_ino == named.st_ino) {
      lock_fd_ = fd;
      break;
    }
    ::close(fd);
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(lock_fd_, 0) == 0) (void)!::pwrite(lock_fd_, pid.data(), pid.size(), 0);
}

OutputFolder::~OutputFolder() { release(); }

void OutputFolder::release() noexcept {
  if (lock_fd_ < 0) return;
  std::error_code ignored;
  fs::remove(folder_ / kLockName, ignored);  // before the unlock: a waiting run then starts again
  ::close(lock_fd_);
  lock_fd_ = -1;
}

void OutputFolder::discard_if_unused() noexcept {
  release();
  created_.remove_empty();
}

}  // namespace feedflow
