#pragma once
// Runs the real feedflow executable many times side by side, each run in its own folder with a
// deadline: exit code or signal, stdout and stderr, and whether it had to be killed (a hang).
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "run_feedflow.hpp"

namespace feedflow::testing {

struct ChildRun {
  std::filesystem::path folder;
  std::vector<std::string> args;  // after the executable
  int exit_code = -1;             // -1 when killed by a signal
  int signal = 0;                 // the signal that ended it, 0 if none
  bool timed_out = false;         // killed at the deadline
  double seconds = 0.0;
  std::string out;
  std::string err;
};

namespace detail {

inline pid_t spawn(const std::string& executable, const ChildRun& run) {
  const std::string folder = run.folder.string();
  const std::string out = (run.folder / ".stdout").string();
  const std::string err = (run.folder / ".stderr").string();
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(executable.c_str()));
  for (const auto& a : run.args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {  // only async-signal-safe calls until exec
    if (::chdir(folder.c_str()) != 0) ::_exit(127);
    const int in_fd = ::open("/dev/null", O_RDONLY);
    const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in_fd < 0 || out_fd < 0 || err_fd < 0) ::_exit(127);
    ::dup2(in_fd, 0);
    ::dup2(out_fd, 1);
    ::dup2(err_fd, 2);
    ::execv(executable.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

}  // namespace detail

// Runs every `runs[i]` (folder and args set) with at most `parallel` at a time, each killed after
// `deadline`; calls `done(run)` as each finishes, in the order they finish.
inline void run_children(const std::string& executable, std::vector<ChildRun>& runs, unsigned parallel,
                         std::chrono::duration<double> deadline, const std::function<void(ChildRun&)>& done) {
  using Clock = std::chrono::steady_clock;
  struct Active {
    pid_t pid;
    std::size_t index;
    Clock::time_point start;
    bool killed = false;
  };
  std::vector<Active> active;
  std::size_t next = 0;
  while (next < runs.size() || !active.empty()) {
    while (next < runs.size() && active.size() < parallel) {
      active.push_back({detail::spawn(executable, runs[next]), next, Clock::now()});
      ++next;
    }
    bool reaped = false;
    for (std::size_t i = 0; i < active.size();) {
      auto& a = active[i];
      int status = 0;
      const pid_t r = ::waitpid(a.pid, &status, WNOHANG);
      if (r == a.pid) {
        ChildRun& run = runs[a.index];
        run.seconds = std::chrono::duration<double>(Clock::now() - a.start).count();
        run.timed_out = a.killed;
        run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        run.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        run.out = slurp(run.folder / ".stdout");
        run.err = slurp(run.folder / ".stderr");
        std::filesystem::remove(run.folder / ".stdout");
        std::filesystem::remove(run.folder / ".stderr");
        done(run);
        active.erase(active.begin() + static_cast<std::ptrdiff_t>(i));
        reaped = true;
        continue;
      }
      if (!a.killed && Clock::now() - a.start > deadline) {
        ::kill(a.pid, SIGKILL);  // our own child, by its pid
        a.killed = true;
      }
      ++i;
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

}  // namespace feedflow::testing
