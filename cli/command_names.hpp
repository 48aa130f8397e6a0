#pragma once
// A mistyped command is named with the closest command there is. CLI11 takes an unknown word
// for an extra argument and says only "A subcommand is required".

#include <CLI/CLI.hpp>

namespace littermap::cli {

// Walks argv down the app's subcommands; throws UsageError "unknown command 'eval trajectry'
// (did you mean 'eval trajectory'?)" at the first word that names none of them.
void CheckCommandNames(CLI::App& app, int argc, const char* const* argv);

}  // namespace littermap::cli
