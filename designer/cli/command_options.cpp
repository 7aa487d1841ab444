#include "designer/cli/command_options.hpp"

#include "designer/cli/exit_codes.hpp"

namespace feedflow {

void add_verbosity_options(Command& command, CommandOptions& options, bool has_json) {
  auto quiet = command.flag("-q,--quiet", options.quiet,
                            has_json ? "print nothing but errors and what --json - sends to stdout"
                                     : "print nothing but errors");
  command.flag("-v,--verbose", options.verbose, "say more about what is done and where")
      .excludes(quiet);
}

void add_json_option(Command& command, CommandOptions& options, const std::string& what) {
  command
      .option("--json", options.json,
              "also write " + what +
                  " to FILE; '-' writes it to stdout and nothing else goes there")
      .type_name("FILE");
}

void add_case_options(Command& command, CommandOptions& options,
                      const std::string& default_folder) {
  command
      .option("--set", options.sets,
              "override a case value, units allowed (repeatable): "
              "--set hopper.semi_angle=32deg")
      .type_name("KEY=VALUE")
      .repeatable();
  add_json_option(command, options, "the results JSON");
  command.option("--out", options.out, "output folder (default: " + default_folder + ")")
      .type_name("DIR");
  add_verbosity_options(command, options, true);
  command
      .option(
          "--fail-on", options.fail_on,
          "exit with code 1 when the verdict is this bad or worse: marginal (MARGINAL, UNKNOWN or "
          "FAIL) or fail (FAIL); default: exit 0 whatever the verdict")
      .one_of({"marginal", "fail"})
      .type_name("VERDICT");
}

int verdict_exit_code(const CommandOptions& options, VerdictStatus verdict) {
  if (options.fail_on.empty()) return kExitOk;
  const bool fails = verdict == VerdictStatus::fail;
  const bool marginal = verdict == VerdictStatus::marginal || verdict == VerdictStatus::unknown;
  return fails || (options.fail_on == "marginal" && marginal) ? kExitVerdict : kExitOk;
}

}  // namespace feedflow
