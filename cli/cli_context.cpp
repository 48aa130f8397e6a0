#include "cli/cli_context.hpp"

#include <cstdio>

namespace littermap::cli {

CLI::App* CliContext::AddCommand(CLI::App& parent, const std::string& name,
                                 const std::string& description) {
  CLI::App* command = parent.add_subcommand(name, description);
  command->add_flag("-q,--quiet", quiet, "No progress output on stderr");
  return command;
}

ProgressCallback CliContext::Progress() {
  if (quiet) return {};
  return [this](const littermap::Progress& progress) {
    if (task_prefix.empty()) {
      display_.Update(progress);
      return;
    }
    const std::string task = task_prefix + std::string(progress.task);
    littermap::Progress prefixed = progress;
    prefixed.task = task;
    display_.Update(prefixed);
  };
}

void CliContext::Status(const std::string& line) {
  if (!quiet) display_.Status(line);
}

void CliContext::Warn(const std::string& message) {
  if (quiet) return;
  display_.Finish();
  std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void CliContext::FinishProgress() { display_.Finish(); }

}  // namespace littermap::cli
