// Subcommands whose stage is not built yet: they are listed in --help with their contract from
// DESIGN.md and exit 1 with a message saying so, so scripts fail loudly rather than silently.

#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "core/error.hpp"

namespace littermap::cli {
namespace {

struct PendingCommand {
  const char* name;
  const char* summary;
};

const std::vector<PendingCommand>& Pending() {
  static const std::vector<PendingCommand> commands = {
      {"report", "HTML report of a site for park staff (not available yet)"},
      {"survey", "reconstruct, detect, ingest, heatmap and report in one go (not available yet)"},
  };
  return commands;
}

}  // namespace

void RegisterPendingCommands(CLI::App& app, CliContext& context) {
  for (const auto& command : Pending()) {
    CLI::App* sub = context.AddCommand(app, command.name, command.summary);
    // Accept and ignore any arguments, so the answer is "not available" rather than a parse error.
    auto ignored = std::make_shared<std::vector<std::string>>();
    sub->add_option("ARGS", *ignored, "Arguments of the future stage")->allow_extra_args();
    sub->allow_extras();
    const std::string name = command.name;
    sub->callback([&context, name, ignored] {
      context.run = [name] {
        throw UsageError("'littermap " + name + "' is not available in this version yet");
      };
    });
  }
}

}  // namespace littermap::cli
