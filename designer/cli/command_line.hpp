#pragma once
// The command line of `feedflow`: subcommands, their options and flags, and parsing. The
// subcommand files declare what they take through this interface; only command_line.cpp sees the
// parser library (CLI11), so it is compiled once instead of in every subcommand's file.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace feedflow {

// One option or flag of a command, as it was added; each setter returns the option again.
class CommandOption {
 public:
  explicit CommandOption(CLI::Option* option) : option_(option) {}
  CommandOption& required();
  // The placeholder the help shows for the value, e.g. "CASE" or "TIME".
  CommandOption& type_name(const std::string& name);
  // The help shows the target's value at the time the option was added as its default.
  CommandOption& show_default();
  // The value must be one of `allowed` (each element of a list option).
  CommandOption& one_of(const std::vector<std::string>& allowed);
  // A list option also splits each value at `separator`: --only a,b.
  CommandOption& delimiter(char separator);
  // A list option takes one value per use and may be repeated: --set a=1 --set b=2.
  CommandOption& repeatable();
  // This option and `other` cannot be given together.
  CommandOption& excludes(const CommandOption& other);

 private:
  CLI::Option* option_;
};

// A command (the program, or one of its subcommands): its options, flags and what it runs.
class Command {
 public:
  explicit Command(CLI::App* app) : app_(app) {}
  Command subcommand(const std::string& name, const std::string& description);
  // A positional argument when `name` has no leading '-', else an option ("-o,--out").
  CommandOption option(const std::string& name, std::string& target, const std::string& help);
  CommandOption option(const std::string& name, std::vector<std::string>& target,
                       const std::string& help);
  CommandOption option(const std::string& name, double& target, const std::string& help);
  CommandOption option(const std::string& name, std::optional<double>& target,
                       const std::string& help);
  CommandOption option(const std::string& name, std::vector<double>& target,
                       const std::string& help);
  CommandOption option(const std::string& name, int& target, const std::string& help);
  CommandOption flag(const std::string& name, bool& target, const std::string& help);
  // What runs when the command is given (after its options are parsed).
  void on_run(std::function<void()> run);

 private:
  CLI::App* app_;
};

// The program's command line: the root command, the version flag, one subcommand required.
class CommandLine {
 public:
  CommandLine(const std::string& description, const std::string& program,
              const std::string& version);
  ~CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  Command root();
  // Parses `argv` and runs the subcommand given. Empty when the subcommand ran; else the exit
  // code of what parsing alone settled: 0 for --help and --version (printed), `bad_input` for a
  // malformed command line (its message printed on stderr). Errors of the subcommand itself
  // propagate to the caller.
  std::optional<int> parse_and_run(int argc, char** argv, int bad_input);

 private:
  std::unique_ptr<CLI::App> app_;
};

}  // namespace feedflow
