#pragma once
// Options every computing subcommand shares: --set, --json, --out, -q, -v.
#include <CLI/CLI.hpp>
#include <iosfwd>
#include <string>
#include <vector>

namespace feedflow {

struct CommandOptions {
  std::vector<std::string> sets;  // "key=value", in order
  std::string json;               // file for the results JSON; "-" is stdout
  std::string out;                // output folder; empty = out/<case name>
  bool quiet = false;
  bool verbose = false;

  bool json_to_stdout() const { return json == "-"; }
  // Where human text goes: stdout, unless the JSON goes there.
  bool human_output() const { return !quiet && !json_to_stdout(); }
};

void add_verbosity_options(CLI::App& command, CommandOptions& options);
void add_json_option(CLI::App& command, CommandOptions& options);
void add_case_options(CLI::App& command, CommandOptions& options);  // all of the above + --set, --out

}  // namespace feedflow
