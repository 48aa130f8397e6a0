#include "cli/cli_context.hpp"

namespace littermap::cli {
void RegisterInfoCommand(CLI::App&, CliContext&) {}
}  // namespace littermap::cli
