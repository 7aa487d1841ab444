#include "designer/cli/command_line.hpp"

#include <CLI/CLI.hpp>

namespace feedflow {

CommandOption& CommandOption::required() {
  option_->required();
  return *this;
}

CommandOption& CommandOption::type_name(const std::string& name) {
  option_->type_name(name);
  return *this;
}

CommandOption& CommandOption::show_default() {
  option_->capture_default_str();
  return *this;
}

CommandOption& CommandOption::one_of(const std::vector<std::string>& allowed) {
  option_->check(CLI::IsMember(allowed));
  return *this;
}

CommandOption& CommandOption::delimiter(char separator) {
  option_->delimiter(separator);
  return *this;
}

CommandOption& CommandOption::repeatable() {
  option_->take_all()->allow_extra_args(false);
  return *this;
}

CommandOption& CommandOption::excludes(const CommandOption& other) {
  option_->excludes(other.option_);
  return *this;
}

Command Command::subcommand(const std::string& name, const std::string& description) {
  return Command(app_->add_subcommand(name, description));
}

CommandOption Command::option(const std::string& name, std::string& target,
                              const std::string& help) {
  return CommandOption(app_->add_option(name, target, help));
}

CommandOption Command::option(const std::string& name, std::vector<std::string>& target,
                              const std::string& help) {
  return CommandOption(app_->add_option(name, target, help));
}

CommandOption Command::option(const std::string& name, double& target, const std::string& help) {
  return CommandOption(app_->add_option(name, target, help));
}

CommandOption Command::option(const std::string& name, std::optional<double>& target,
                              const std::string& help) {
  return CommandOption(app_->add_option(name, target, help));
}

CommandOption Command::option(const std::string& name, std::vector<double>& target,
                              const std::string& help) {
  return CommandOption(app_->add_option(name, target, help));
}

CommandOption Command::option(const std::string& name, int& target, const std::string& help) {
  return CommandOption(app_->add_option(name, target, help));
}

CommandOption Command::flag(const std::string& name, bool& target, const std::string& help) {
  return CommandOption(app_->add_flag(name, target, help));
}

void Command::on_run(std::function<void()> run) { app_->callback(std::move(run)); }

CommandLine::CommandLine(const std::string& description, const std::string& program,
                         const std::string& version)
    : app_(std::make_unique<CLI::App>(description, program)) {
  app_->set_version_flag("--version", version);
  app_->require_subcommand(1);
}

CommandLine::~CommandLine() = default;

Command CommandLine::root() { return Command(app_.get()); }

std::optional<int> CommandLine::parse_and_run(int argc, char** argv, int bad_input) {
  try {
    app_->parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app_->exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app_->exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app_->exit(e);
  } catch (const CLI::ParseError& e) {
    app_->exit(e);
    return bad_input;
  }
  return std::nullopt;
}

}  // namespace feedflow
