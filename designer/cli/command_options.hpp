#pragma once
// Options every computing subcommand shares: --set, --json, --out, -q, -v.
#include <iosfwd>
#include <string>
#include <vector>
#include "designer/cli/command_line.hpp"

#include "models/core/design_record.hpp"

namespace feedflow {

struct CommandOptions {
  std::vector<std::string> sets;  // "key=value", in order
  std::string json;               // file for the results JSON; "-" is stdout
  std::string out;                // output folder; empty = the command's default
  bool quiet = false;
  bool verbose = false;
  std::string fail_on;            // "marginal" | "fail": the verdict that makes the exit code 1

  bool json_to_stdout() const { return json == "-"; }
  // Where human text goes: stdout, unless the JSON goes there.
  bool human_output() const { return !quiet && !json_to_stdout(); }
};

// -q and -v; `has_json`: the command has --json (whose '-' copy -q keeps).
void add_verbosity_options(Command& command, CommandOptions& options, bool has_json);
// --json FILE; `what` names what is written: "the results JSON".
void add_json_option(Command& command, CommandOptions& options, const std::string& what);
// All of the above + --set, --out and --fail-on; `default_folder` says where --out defaults to.
void add_case_options(Command& command, CommandOptions& options, const std::string& default_folder);

// The exit code of a finished check: kExitVerdict when --fail-on asks for it and the verdict is
// that bad or worse (fail > marginal; unknown counts as marginal), else kExitOk.
int verdict_exit_code(const CommandOptions& options, VerdictStatus verdict);

}  // namespace feedflow
