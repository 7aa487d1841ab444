#include "models/os/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace feedflow {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
  throw std::runtime_error("cannot write " + path.string() + ": " + why);
}

std::string system_reason(int error) { return std::strerror(error); }

struct Resolved {
  fs::path target;
  bool special = false;
};

// What `path` names, following links (stat follows them, /proc/self/fd/1 included).
Resolved resolve(const fs::path& path) {
  struct stat followed {};
  struct stat own {};
  const bool is_link = ::lstat(path.c_str(), &own) == 0 && S_ISLNK(own.st_mode);
  if (::stat(path.c_str(), &followed) != 0) {
    const int error = errno;
    if (error == ELOOP) refuse(path, "a symbolic link loop");
    if (error == ENOENT && is_link)
      refuse(path, "a symbolic link to " + fs::read_symlink(path).string() +
                       ", which does not exist; give the target's own path");
    if (error == ENOENT) return {path, false};  // a new file
    if (error == ENOTDIR) refuse(path, "a part of the path is a file, not a folder");
    refuse(path, system_reason(error));
  }
  const mode_t mode = followed.st_mode;
  if (S_ISDIR(mode)) refuse(path, "it is a folder; give a file name");
  if (S_ISBLK(mode)) refuse(path, "it is a block device; feedflow writes no disk devices");
  if (S_ISSOCK(mode)) refuse(path, "it is a socket");
  if (!S_ISREG(mode)) return {path, true};  // a FIFO, a terminal, a character device
  if (!is_link) return {path, false};
  std::error_code ec;
  fs::path target = fs::canonical(path, ec);
  if (ec) refuse(path, "cannot follow the symbolic link: " + ec.message());
  return {target, false};
}

}  // namespace

void write_all(int fd, std::string_view content, const std::string& what) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write " + what + ": " + system_reason(n < 0 ? errno : EIO));
    done += static_cast<std::size_t>(n);
  }
}

PendingFile::PendingFile(const fs::path& path, std::string_view content) : path_(path) {
  std::error_code ec;
  if (path.has_parent_path() && !fs::exists(path.parent_path(), ec)) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) refuse(path, "cannot create folder " + path.parent_path().string() + ": " + ec.message());
  }
  const Resolved r = resolve(path);
  target_ = r.target;
  special_ = r.special;
  if (special_) {
    content_ = std::string(content);
    return;
  }
  const fs::path temporary = target_.string() + ".tmp" + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) refuse(target_, system_reason(errno));
  temporary_ = temporary;  // from here on the destructor removes it
  try {
    write_all(fd, content, target_.string());
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) refuse(target_, system_reason(errno));
}

PendingFile::PendingFile(PendingFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      content_(std::move(other.content_)),
      special_(other.special_) {
  other.temporary_.clear();
}

PendingFile::~PendingFile() {
  if (temporary_.empty()) return;
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void PendingFile::commit() {
  if (special_) {
    // No O_CREAT: the special file is there; a FIFO waits for its reader, as with `> fifo`.
    const int fd = ::open(path_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) refuse(path_, system_reason(errno));
    try {
      write_all(fd, content_, path_.string());
    } catch (...) {
      ::close(fd);
      throw;
    }
    if (::close(fd) != 0) refuse(path_, system_reason(errno));
    return;
  }
  std::error_code ec;
  fs::rename(temporary_, target_, ec);
  if (ec) refuse(target_, ec.message());
  temporary_.clear();
}

void write_file_atomically(const fs::path& path, std::string_view content) {
  PendingFile(path, content).commit();
}

}  // namespace feedflow
