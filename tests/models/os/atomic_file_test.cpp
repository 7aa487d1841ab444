// Output files appear whole or not at all (models/os/atomic_file).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "models/os/atomic_file.hpp"

namespace feedflow {
namespace {

// An atomic write creates folders, replaces the old file whole and leaves no temporary behind;
// an unwritable target throws and leaves nothing.
TEST(AtomicFile, WritesWholeOrNothing) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "feedflow_atomic_test";
  fs::remove_all(dir);
  write_file_atomically(dir / "a" / "r.json", "first");
  write_file_atomically(dir / "a" / "r.json", "second");
  std::ifstream in(dir / "a" / "r.json");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(content, "second");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "a"), fs::directory_iterator{}), 1);
  std::ofstream(dir / "file") << "x";
  EXPECT_THROW(write_file_atomically(dir / "file" / "r.json", "y"), std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace feedflow
