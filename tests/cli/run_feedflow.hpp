#pragma once
// Runs the real feedflow executable in a folder and captures its exit code, stdout and stderr.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace feedflow::testing {

struct Run {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh folder for the running test, <tmp>/<prefix>_<test name>_<pid> (the pid keeps two
// checkouts testing at once apart), holding a copy of cases/ when asked (a user's checkout).
inline std::filesystem::path scratch_folder(const std::string& prefix, bool with_cases) {
  namespace fs = std::filesystem;
  const auto dir = fs::temp_directory_path() /
                   (prefix + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                    "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (with_cases)
    fs::copy(fs::path(FEEDFLOW_SOURCE_DIR) / "cases", dir / "cases", fs::copy_options::recursive);
  return dir;
}

// `args` is appended to the command line as is (the caller quotes). stdout goes to a file that
// is read back, or to `stdout_to` when given (e.g. /dev/full; r.out is then empty).
inline Run run_feedflow(const std::string& args, const std::filesystem::path& folder,
                        const std::string& stdout_to = "") {
  const auto out = stdout_to.empty() ? folder / ".stdout" : std::filesystem::path(stdout_to);
  const auto err = folder / ".stderr";
  const std::string command = "cd '" + folder.string() + "' && '" FEEDFLOW_EXECUTABLE "' " + args +
                              " > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
  const int status = std::system(command.c_str());
  Run r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = stdout_to.empty() ? slurp(out) : "";
  r.err = slurp(err);
  if (stdout_to.empty()) std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// The standard output of a shell command (pdftotext, pdfimages); empty when it cannot run.
inline std::string command_output(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  pclose(pipe);
  return out;
}

// The text of a PDF (pdftotext; `layout` keeps the columns of tables).
inline std::string pdf_text(const std::filesystem::path& pdf, bool layout = false) {
  return command_output(std::string("pdftotext ") + (layout ? "-layout '" : "'") + pdf.string() +
                        "' -");
}

}  // namespace feedflow::testing
