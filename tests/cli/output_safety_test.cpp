// Where the real `feedflow` writes, and where it must not: links, FIFOs and devices as --json
// targets, a full stdout, a folder named as a file, case names that climb out of out/, and two
// runs into one output folder.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <atomic>
#include <chrono>
#include <thread>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class OutputSafety : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_outputs", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// --json onto a link replaces the link's target (in the target's folder) and keeps the link.
TEST_F(OutputSafety, JsonOntoSymlinkWritesItsTargetAndKeepsTheLink) {
  fs::create_directories(dir_ / "elsewhere");
  std::ofstream(dir_ / "elsewhere/t.json") << "old";
  fs::create_symlink("elsewhere/t.json", dir_ / "link.json");
  const auto r = run_feedflow("design cases/pilot_hopper.toml --json link.json --out o", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
  EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / "elsewhere/t.json")).at("case").at("kind"), "hopper");
  EXPECT_NE(r.out.find("elsewhere/t.json"), std::string::npos) << "the Written: line names the target";
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "elsewhere"), fs::directory_iterator{}), 1);
}

// A dangling link, a link loop and a folder are refused (exit 2, naming --json and the path),
// and nothing else is written.
TEST_F(OutputSafety, JsonOntoFolderOrBrokenLinkWritesNothing) {
  fs::create_directories(dir_ / "folder");
  fs::create_symlink("nowhere.json", dir_ / "dangling.json");
  fs::create_symlink("loop_b", dir_ / "loop_a");
  fs::create_symlink("loop_a", dir_ / "loop_b");
  for (const char* target : {"folder", "dangling.json", "loop_a"}) {
    SCOPED_TRACE(target);
    const auto r = run_feedflow(std::string("design cases/pilot_hopper.toml --json ") + target + " --out o", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(std::string("--json: cannot write ") + target + ": "), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("Success"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "o")) << "results left behind";
  }
  EXPECT_TRUE(fs::is_directory(dir_ / "folder"));
  EXPECT_TRUE(fs::is_empty(dir_ / "folder"));
}

// A FIFO is written through (its reader gets the JSON) and stays a FIFO.
TEST_F(OutputSafety, JsonOntoFifoWritesThrough) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader that never blocks: it drains the FIFO until the run has ended, so a feedflow that
  // replaced the FIFO instead fails the test rather than hanging it.
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  std::atomic<bool> done{false};
  std::string received;
  std::thread reader([&] {
    char buffer[4096];
    for (;;) {
      const bool finished = done;
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n > 0) received.append(buffer, static_cast<std::size_t>(n));
      else if (finished) break;
      else std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  const auto r = run_feedflow("design cases/pilot_hopper.toml --json pipe --out o", dir_);
  done = true;
  reader.join();
  ::close(fd);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(nlohmann::json::parse(received).at("case").at("name"), "pilot_hopper");
}

// A character device is written through, not replaced: --json /proc/self/fd/1 reaches the
// device the shell put on stdout. /dev/full fails the write: an error naming the path, and no
// results left. (The devices are named through /proc, where no file can be created, so that a
// feedflow that replaced its target could not destroy a device node of the machine.)
TEST_F(OutputSafety, JsonOntoDevicesWritesThroughAndFailsLoudly) {
  const auto full = run_feedflow("design cases/pilot_hopper.toml --json /proc/self/fd/1 --out o -q", dir_,
                                 "/dev/full");
  EXPECT_EQ(full.exit_code, 2);
  EXPECT_NE(full.err.find("--json: cannot write /proc/self/fd/1: No space left on device"), std::string::npos)
      << full.err;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
  const auto null = run_feedflow("design cases/pilot_hopper.toml --json /proc/self/fd/1 --out o -q", dir_,
                                 "/dev/null");
  EXPECT_EQ(null.exit_code, 0) << null.err;
  EXPECT_TRUE(fs::exists(dir_ / "o/results.json"));
}

// --json - onto a full stdout fails with a named error and leaves no folder; so does the
// summary a plain run prints.
TEST_F(OutputSafety, FullStdoutIsAnError) {
  const auto json = run_feedflow("design cases/pilot_hopper.toml --json -", dir_, "/dev/full");
  EXPECT_EQ(json.exit_code, 2);
  EXPECT_NE(json.err.find("--json: cannot write the results JSON to stdout"), std::string::npos) << json.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const auto text = run_feedflow("materials", dir_, "/dev/full");
  EXPECT_EQ(text.exit_code, 2);
  EXPECT_NE(text.err.find("cannot write to stdout"), std::string::npos) << text.err;
}

// --json - without --out writes no folder (loops do not overwrite each other); with --out it
// writes there too.
TEST_F(OutputSafety, JsonToStdoutWritesNoFolderUnlessAsked) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml --json -", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("case").at("name"), "pilot_hopper");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  EXPECT_EQ(run_feedflow("design cases/pilot_hopper.toml --json - --out o", dir_).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "o/results.json"));
}

// A case named "../../escaped" (or with any other path characters) stays inside out/.
TEST_F(OutputSafety, CaseNameCannotLeaveOut) {
  std::string text = slurp(dir_ / "cases/pilot_hopper.toml");
  text.replace(text.find("name = \"pilot_hopper\""), 21, "name = \"../../escaped\"");
  fs::create_directories(dir_ / "a/b");
  std::ofstream(dir_ / "a/b/esc.toml") << text;
  fs::create_directories(dir_ / "a/b/materials");
  fs::copy(dir_ / "cases/materials", dir_ / "a/b/materials", fs::copy_options::recursive);
  const auto r = run_feedflow("design esc.toml -q", dir_ / "a/b");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "escaped"));
  EXPECT_FALSE(fs::exists(dir_ / "a/escaped"));
  ASSERT_TRUE(fs::is_directory(dir_ / "a/b/out"));
  const auto folders = std::distance(fs::directory_iterator(dir_ / "a/b/out"), fs::directory_iterator{});
  EXPECT_EQ(folders, 1);
  for (const auto& entry : fs::directory_iterator(dir_ / "a/b/out")) {
    EXPECT_EQ(entry.path().filename().string().find('/'), std::string::npos);
    EXPECT_NE(entry.path().filename().string().front(), '.');
    EXPECT_TRUE(fs::exists(entry.path() / "results.json"));
  }
}

// A folder another run holds (its lock taken) is refused at once: "output folder in use",
// exit 2, nothing run or written; a finished run leaves no lock file behind.
TEST_F(OutputSafety, SecondRunIntoOneFolderIsRefused) {
  fs::create_directories(dir_ / "sim");
  const fs::path lock = dir_ / "sim/.feedflow.lock";
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  (void)!::write(fd, "4242\n", 5);
  for (const char* cmd : {"simulate cases/rotating_drum_20rpm.toml --solver dem --set dem.slab_depth=8mm "
                          "--set drum.diameter=40mm --set drum.fill_fraction=30% --time 0.01s --out sim",
                          "design cases/rotating_drum_20rpm.toml --out sim"}) {
    SCOPED_TRACE(cmd);
    const auto r = run_feedflow(cmd, dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--out: output folder sim in use by another feedflow run (pid 4242)"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "sim/results.json"));
  }
  ::close(fd);  // the other run ends
  const auto r = run_feedflow("design cases/rotating_drum_20rpm.toml --out sim -q", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "sim/results.json"));
  EXPECT_FALSE(fs::exists(lock)) << "the lock file outlives the run";
}

}  // namespace
