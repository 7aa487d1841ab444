#pragma once
// Output files appear whole or not at all: written beside the target, then renamed over it.
// A run that fails half-way leaves nothing half-written.
//
// What a path may name:
// - nothing yet, or a regular file: replaced atomically (a temporary beside it, then a rename);
// - a symbolic link to a regular file: the link's target is replaced atomically in the
//   target's own folder and the link stays; `target()` names the file really written;
// - a special file that cannot be replaced (a FIFO, a terminal, /dev/stdout, /dev/null, a
//   character device): written through, in place; a write error (/dev/full) is an error;
// - a folder, a block device, a socket, a dangling link or a link loop: refused, naming it.
#include <filesystem>
#include <string>
#include <string_view>

namespace feedflow {

// Writes `content` to `path`, creating parent folders. Throws std::runtime_error naming the
// path when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// One output file, staged: the constructor checks the target and writes the temporary (a
// regular target) or only checks (a special file); commit() puts the content in place. A
// PendingFile destroyed without commit() removes its temporary, so a set of files can be
// written all or none: stage them all, then commit them all. Throws std::runtime_error naming
// the path.
class PendingFile {
 public:
  PendingFile(const std::filesystem::path& path, std::string_view content);
  PendingFile(PendingFile&& other) noexcept;
  PendingFile& operator=(PendingFile&&) = delete;
  PendingFile(const PendingFile&) = delete;
  ~PendingFile();

  void commit();
  // The file the content goes to: the path, or a link's target.
  const std::filesystem::path& target() const { return target_; }
  bool is_special() const { return special_; }

 private:
  std::filesystem::path path_;       // as given
  std::filesystem::path target_;     // resolved through a link
  std::filesystem::path temporary_;  // empty for a special file or after commit
  std::string content_;              // kept for a special file only
  bool special_ = false;
};

// Writes all of `content` to an open file descriptor (stdout, a FIFO); throws
// std::runtime_error naming `what` and the system's reason when a write fails.
void write_all(int fd, std::string_view content, const std::string& what);

}  // namespace feedflow
