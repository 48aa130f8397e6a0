// littermap convert BAG -o OUT [--storage mcap|sqlite3] [--compression zstd|lz4|none]
//   [--topics T...]: the same messages in another storage (bag/bag_convert.hpp).

#include <cstdio>
#include <memory>

#include "bag/bag_convert.hpp"
#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"

namespace littermap::cli {

void RegisterConvertCommand(CLI::App& app, CliContext& context) {
  struct Arguments {
    std::string input, output, compression = "zstd";
    bag::ConvertOptions options;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = context.AddCommand(
      app, "convert", "Copy a bag into MCAP or sqlite3 storage, losslessly (or some topics only)");
  command->add_option("BAG", arguments->input, "Bag directory (or one .db3/.mcap file)")
      ->required()
      ->check(ExistingInput(InputKind::kFileOrFolder));
  command->add_option("-o,--output", arguments->output, "Bag directory to write")->required();
  command->add_option("--storage", arguments->options.storage, "Storage of the new bag")
      ->check(CLI::IsMember({"mcap", "sqlite3"}))
      ->capture_default_str();
  command->add_option("--compression", arguments->compression, "MCAP chunk compression")
      ->check(CLI::IsMember({"zstd", "lz4", "none"}))
      ->capture_default_str();
  command->add_option("--topics", arguments->options.topics, "Copy only these topics");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] {
      arguments->options.mcap.compression = bag::ParseMcapCompression(arguments->compression);
      const auto result = bag::ConvertBag(arguments->input, arguments->output, arguments->options,
                                          context.Progress());
      context.FinishProgress();
      for (const auto& warning : result.warnings) context.Warn(warning);
      std::printf("wrote %s: %llu messages on %zu topics, %s storage, %.1f MiB\n",
                  arguments->output.c_str(), static_cast<unsigned long long>(result.message_count),
                  result.topic_count, arguments->options.storage.c_str(),
                  static_cast<double>(result.output_bytes) / (1024.0 * 1024.0));
    };
  });
}

}  // namespace littermap::cli
