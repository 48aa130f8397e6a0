#pragma once
// State shared by the littermap subcommands: global flags, the chosen command, and the way
// progress and warnings reach the user (stderr; results go to files and stdout).

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/progress_display.hpp"
#include "core/progress.hpp"

namespace littermap::cli {

class CliContext {
 public:
  bool quiet = false;
  std::function<void()> run;  // set by the callback of the subcommand that was given
  std::string task_prefix;    // put before every progress task, e.g. "[2/5 detect] "

  // Adds a subcommand that also accepts the global flags (--quiet) after its name.
  CLI::App* AddCommand(CLI::App& parent, const std::string& name, const std::string& description);

  ProgressCallback Progress();
  void Status(const std::string& line);  // see ProgressDisplay::Status; nothing with --quiet
  void Warn(const std::string& message);
  void FinishProgress();

 private:
  ProgressDisplay display_;
};

// Each file cmd_*.cpp adds its subcommand(s) to the app.
void RegisterInfoCommand(CLI::App& app, CliContext& context);
void RegisterConvertCommand(CLI::App& app, CliContext& context);
void RegisterImportCommands(CLI::App& app, CliContext& context);
void RegisterSimulateCommand(CLI::App& app, CliContext& context);
void RegisterCaptureCommand(CLI::App& app, CliContext& context);
void RegisterReconstructCommand(CLI::App& app, CliContext& context);
void RegisterEvalCommands(CLI::App& app, CliContext& context);
void RegisterSiteCommands(CLI::App& app, CliContext& context);
void RegisterIngestCommand(CLI::App& app, CliContext& context);
void RegisterHeatmapCommand(CLI::App& app, CliContext& context);
void RegisterReportCommand(CLI::App& app, CliContext& context);
void RegisterSurveyCommand(CLI::App& app, CliContext& context);
void RegisterDetectCommand(CLI::App& app, CliContext& context);
void RegisterTrainCommands(CLI::App& app, CliContext& context);
// Add `eval map`, `eval settle` and `eval detections` to the `eval` command; call after
// RegisterEvalCommands.
void RegisterEvalMapCommand(CLI::App& app, CliContext& context);
void RegisterEvalSettleCommand(CLI::App& app, CliContext& context);
void RegisterEvalDetectionsCommand(CLI::App& app, CliContext& context);
// Adds `eval segmentation` to the `eval` command; call after RegisterEvalCommands.
void RegisterEvalSegmentationCommand(CLI::App& app, CliContext& context);
// Adds `eval relations` to the `eval` command; call after RegisterEvalCommands.
void RegisterEvalRelationsCommand(CLI::App& app, CliContext& context);

}  // namespace littermap::cli
