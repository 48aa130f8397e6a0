// littermap import carmen LOG[.gz] -o BAG [--reference REF.tum] [--odometry-noise SEED]
// littermap import tum DIR -o BAG [--reference REF.tum] [--camera fr1|fr2|fr3]
// Foreign logs into run bags (DESIGN.md, "The command line").

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "core/error.hpp"
#include "importers/import_summary.hpp"

namespace littermap::cli {
namespace {

struct ImportArguments {
  std::string input;  // the log file or the sequence directory
  std::string bag;
  std::string reference;
  std::string camera;  // tum only
  importers::CarmenImportOptions carmen;
  importers::TumImportOptions tum;
};

void PrintImport(const std::string& summary, const std::vector<std::string>& warnings,
                 CliContext& context) {
  context.FinishProgress();
  for (const std::string& warning : warnings) context.Warn(warning);
  std::fputs(summary.c_str(), stdout);
}

void RunCarmen(ImportArguments arguments, CliContext& context) {
  arguments.carmen.reference_path = arguments.reference;
  const importers::CarmenImportResult result = importers::ImportCarmenLog(
      arguments.input, arguments.bag, arguments.carmen, context.Progress());
  PrintImport(importers::ImportSummary(arguments.bag, arguments.carmen, result), result.warnings,
              context);
}

void RunTum(ImportArguments arguments, CliContext& context) {
  arguments.tum.reference_path = arguments.reference;
  if (!arguments.camera.empty()) {
    arguments.tum.camera = importers::ParseTumCamera(arguments.camera);
    if (!arguments.tum.camera) {
      throw UsageError("--camera: '" + arguments.camera + "' is not one of fr1, fr2, fr3");
    }
  }
  const importers::TumImportResult result = importers::ImportTumSequence(
      arguments.input, arguments.bag, arguments.tum, context.Progress());
  PrintImport(importers::ImportSummary(arguments.bag, arguments.tum, result), result.warnings,
              context);
}

// -o and --reference of both importers, after their input.
void AddOutputs(CLI::App& command, ImportArguments& arguments, const std::string& reference) {
  command.add_option("-o,--output", arguments.bag, "Bag directory to create")->required();
  command.add_option("--reference", arguments.reference, reference);
}

void OnRun(CLI::App& command, std::shared_ptr<ImportArguments> arguments, CliContext& context,
           void (*run)(ImportArguments, CliContext&)) {
  command.callback([arguments, &context, run] {
    context.run = [arguments, &context, run] { run(*arguments, context); };
  });
}

void RegisterCarmen(CLI::App& import, CliContext& context) {
  auto arguments = std::make_shared<ImportArguments>();
  CLI::App* carmen = context.AddCommand(
      import, "carmen",
      "Import a CARMEN laser log (plain or .gz): /scan, /odom and /tf_static (base_link -> laser)");
  carmen->add_option("LOG", arguments->input, "CARMEN log file, plain text or gzip")
      ->required()
      ->check(ExistingInput(InputKind::kFile));
  AddOutputs(*carmen, *arguments,
             "Also write the log's (corrected) robot poses, one per scan, as a TUM "
             "trajectory file");
  carmen
      ->add_option("--odometry-noise", arguments->carmen.odometry_noise_seed,
                   "Replace the odometry by the reference corrupted with seeded Gaussian noise "
                   "(5 % of distance for dx, dy; 5 % of turn + 1 deg/m + 0.1 deg for dtheta)")
      ->check(Seed());
  OnRun(*carmen, arguments, context, RunCarmen);
}

void RegisterTum(CLI::App& import, CliContext& context) {
  auto arguments = std::make_shared<ImportArguments>();
  CLI::App* tum = context.AddCommand(
      import, "tum",
      "Import a TUM RGB-D sequence directory (rgb.txt, depth.txt, rgb/, depth/): colour, "
      "depth in mm and camera_info");
  tum->add_option("DIR", arguments->input, "TUM RGB-D sequence directory")
      ->required()
      ->check(ExistingInput(InputKind::kFolder));
  AddOutputs(*tum, *arguments, "Also write groundtruth.txt's poses as a TUM trajectory file");
  tum->add_option("--camera", arguments->camera,
                  "TUM camera calibration fr1|fr2|fr3 (default: from the directory name, e.g. "
                  "rgbd_dataset_freiburg2_desk)");
  OnRun(*tum, arguments, context, RunTum);
}

}  // namespace

void RegisterImportCommands(CLI::App& app, CliContext& context) {
  CLI::App* import =
      context.AddCommand(app, "import", "Convert foreign logs (CARMEN, TUM RGB-D) into run bags");
  import->require_subcommand(1);
  RegisterCarmen(*import, context);
  RegisterTum(*import, context);
}

}  // namespace littermap::cli
