// Subcommands whose names are taken but whose work comes with later releases. They accept any
// arguments and say plainly that they are not available (exit code 3); they never pretend.
#include "designer/cli/commands.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

struct Reserved {
  const char* name;
  const char* what;
};

constexpr Reserved kReserved[] = {
    {"sweep", "run a what-if sweep over case values"},
};

}  // namespace

void add_reserved_commands(CLI::App& app, int&) {
  for (const auto& r : kReserved) {
    auto* command = app.add_subcommand(r.name, std::string(r.what) + " (not yet available)");
    command->allow_extras();
    const std::string name = r.name;
    command->callback([name] {
      throw NotAvailable("feedflow " + name + " is not yet available in this build");
    });
  }
}

}  // namespace feedflow
