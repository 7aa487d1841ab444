#pragma once
// The folder a run writes into. Claimed before the run writes anything: created when missing
// and locked (flock on <folder>/.feedflow.lock, holding the owner's pid) so that two runs never
// write into one folder; released, and the lock file removed, when the claim ends (the kernel
// drops the lock of a process that dies). A run that fails removes the folder again when it
// created it and left nothing in it.
#include <filesystem>
#include <string>
#include <vector>

namespace feedflow {

// Folders made by `create` (outermost first), so that a failed run can take them back.
class CreatedFolders {
 public:
  // Creates `folder` and its missing parents; throws std::runtime_error naming the folder.
  void create(const std::filesystem::path& folder);
  // Removes the folders this made, deepest first, while they are empty.
  void remove_empty() noexcept;

 private:
  std::vector<std::filesystem::path> made_;
};

class OutputFolder {
 public:
  // Creates and locks `folder`. Throws InputError(option, ...) when it cannot be created or
  // another feedflow run holds it ("output folder in use").
  OutputFolder(std::filesystem::path folder, const std::string& option);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  ~OutputFolder();  // releases the lock

  const std::filesystem::path& path() const { return folder_; }
  // After a failure: releases the lock and removes the folders the claim created if the run
  // left them empty.
  void discard_if_unused() noexcept;

  static constexpr const char* kLockName = ".feedflow.lock";

 private:
  void release() noexcept;

  std::filesystem::path folder_;
  CreatedFolders created_;
  int lock_fd_ = -1;
};

}  // namespace feedflow
