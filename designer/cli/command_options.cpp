#include "designer/cli/command_options.hpp"

namespace feedflow {

void add_verbosity_options(CLI::App& command, CommandOptions& options) {
  auto* quiet = command.add_flag("-q,--quiet", options.quiet,
                                 "print nothing but errors and what --json sends to stdout");
  command.add_flag("-v,--verbose", options.verbose, "say more about what is done and where")
      ->excludes(quiet);
}

void add_json_option(CLI::App& command, CommandOptions& options) {
  command.add_option("--json", options.json,
                     "also write the results JSON to FILE; '-' writes it to stdout and nothing "
                     "else goes there")
      ->type_name("FILE");
}

void add_case_options(CLI::App& command, CommandOptions& options) {
  command.add_option("--set", options.sets,
                     "override a case value, units allowed (repeatable): "
                     "--set hopper.semi_angle=32deg")
      ->type_name("KEY=VALUE")
      ->take_all()
      ->allow_extra_args(false);
  add_json_option(command, options);
  command.add_option("--out", options.out, "output folder (default: out/<case name>)")
      ->type_name("DIR");
  add_verbosity_options(command, options);
}

}  // namespace feedflow
