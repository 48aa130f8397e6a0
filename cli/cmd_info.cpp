// littermap info BAG [--json] [--reindex] [--verify]: what a run bag holds, like `ros2 bag info`.

#include <cstdio>
#include <memory>
#include <string>

#include "bag/bag_summary.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"

namespace littermap::cli {
namespace {

struct InfoArguments {
  std::string bag;
  bool json = false;
  bag::BagSummaryOptions options;
};

void RunInfo(const InfoArguments& arguments, CliContext& context) {
  const bag::BagSummary summary =
      bag::SummariseBag(arguments.bag, arguments.options, context.Progress(),
                        [&context](const std::string& warning) { context.Warn(warning); });
  context.FinishProgress();
  std::fputs((arguments.json ? bag::ToJson(summary) + "\n" : bag::ToText(summary)).c_str(), stdout);
  // The rest of the bag was read and reported; the recording is still damaged.
  if (!summary.damage.empty()) {
    throw BadInputError(summary.damage.front() +
                        (summary.damage.size() > 1
                             ? " (and " + std::to_string(summary.damage.size() - 1) + " more)"
                             : ""));
  }
}

}  // namespace

void RegisterInfoCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<InfoArguments>();
  CLI::App* info =
      context.AddCommand(app, "info", "Show the topics, counts and duration of a run bag");
  info->add_option("BAG", arguments->bag, "Bag directory (or one .db3 or .mcap file)")->required();
  info->add_flag("--json", arguments->json, "Machine-readable output with stable keys");
  info->add_flag("--reindex", arguments->options.reindex,
                 "Rewrite metadata.yaml from the database (after an interrupted recording)");
  info->add_flag("--verify", arguments->options.verify,
                 "Decode every message; a damaged one is an error naming topic and index, damaged "
                 "storage (an MCAP chunk) one naming file and offset");
  info->callback([arguments, &context] {
    context.run = [arguments, &context] { RunInfo(*arguments, context); };
  });
}

}  // namespace littermap::cli
