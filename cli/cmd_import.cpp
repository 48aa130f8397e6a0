#include "cli/cli_context.hpp"

namespace littermap::cli {
void RegisterImportCommands(CLI::App&, CliContext&) {}
}  // namespace littermap::cli
