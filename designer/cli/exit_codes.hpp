#pragma once
// Exit codes of the feedflow command (README, "Command line").
namespace feedflow {

enum ExitCode : int {
  kExitOk = 0,
  kExitVerdict = 1,         // --fail-on: the verdict was that bad or worse
  kExitBadInput = 2,        // usage, case file, units, ranges
  kExitNotAvailable = 3,    // a command this build does not have yet
  kExitNumericalFailure = 4,
  kExitInterrupted = 130,   // Ctrl-C: a checkpoint was written (128 + SIGINT)
};

}  // namespace feedflow
