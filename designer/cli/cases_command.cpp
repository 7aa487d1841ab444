// feedflow cases: the case files in a folder, one line each.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "designer/case/case_loader.hpp"
#include "designer/case/shipped_cases.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/output_files.hpp"
#include "models/core/errors.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

struct CasesArguments {
  std::string folder;
  CommandOptions options;
};

int list_cases(const CasesArguments& args) {
  const fs::path folder =
      args.folder.empty() ? shipped_case_root() / "cases" : fs::path(args.folder);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError("--dir", "", "no such folder: " + folder.string());
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator(folder, ec))
    if (item.is_regular_file() && item.path().extension() == ".toml") files.push_back(item.path());
  std::sort(files.begin(), files.end());

  nlohmann::ordered_json json = nlohmann::ordered_json::array();
  if (args.options.human_output())
    std::printf("%-36s %-7s %s\n", "FILE", "KIND", "DESCRIPTION");
  for (const auto& file : files) {
    const CaseSummary s = summarize_case(file.string());
    json.push_back({{"file", file.string()}, {"name", s.name}, {"kind", s.kind},
                    {"description", s.description}});
    if (args.options.human_output())
      std::printf("%-36s %-7s %s\n", file.string().c_str(), s.kind.c_str(), s.description.c_str());
  }
  write_json_copy(json.dump(2) + "\n", args.options);
  return 0;
}

}  // namespace

void add_cases_command(Command& program, int& exit_code) {
  auto args = std::make_shared<CasesArguments>();
  auto command =
      program.subcommand("cases", "list the case files with a one-line description each");
  command.option("--dir", args->folder, "folder to list (default: ./cases)").type_name("DIR");
  add_json_option(command, args->options, "the case list as JSON");
  add_verbosity_options(command, args->options, true);
  command.on_run([args, &exit_code] { exit_code = list_cases(*args); });
}

}  // namespace feedflow
