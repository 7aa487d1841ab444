// feedflow version
#include <iostream>

#include "designer/cli/commands.hpp"
#include "models/core/commit.hpp"
#include "models/core/version.hpp"

namespace feedflow {

void add_version_command(Command& program, int& exit_code) {
  auto command = program.subcommand("version", "print the feedflow version");
  command.on_run([&exit_code] {
    std::cout << "feedflow " << kVersion << " (commit " << kCommit << ", built with g++ " << __VERSION__ << ", C++"
              << __cplusplus / 100 % 100 << ")\n";
    exit_code = 0;
  });
}

}  // namespace feedflow
