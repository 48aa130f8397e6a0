// littermap import carmen LOG[.gz] -o BAG [--reference REF.tum] [--odometry-noise SEED]
// littermap import tum DIR -o BAG [--reference REF.tum] [--camera fr1|fr2|fr3]
// Foreign logs into run bags (DESIGN.md, "The command line").

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "importers/carmen_importer.hpp"
#include "importers/tum_importer.hpp"

namespace littermap::cli {
namespace {

struct CarmenArguments {
  std::string log;
  std::string bag;
  std::string reference;
  std::optional<std::uint64_t> noise_seed;
};

struct TumArguments {
  std::string directory;
  std::string bag;
  std::string reference;
  std::string camera;
};

std::string Skipped(const importers::CarmenImportResult& result) {
  std::string text;
  for (const auto& [type, count] : result.skipped_types) {
    text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + type;
  }
  if (result.odom_records_ignored > 0) {
    text += (text.empty() ? "" : ", ") + std::to_string(result.odom_records_ignored) + " ODOM";
  }
  return text.empty() ? "" : " (not imported: " + text + ")";
}

void RunCarmen(const CarmenArguments& arguments, CliContext& context) {
  importers::CarmenImportOptions options;
  options.reference_path = arguments.reference;
  options.odometry_noise_seed = arguments.noise_seed;
  const importers::CarmenImportResult result =
      importers::ImportCarmenLog(arguments.log, arguments.bag, options, context.Progress());
  context.FinishProgress();
  for (const std::string& warning : result.warnings) context.Warn(warning);
  std::string beams = std::to_string(result.beam_count_min);
  if (result.beam_count_max != result.beam_count_min) {
    beams += "-" + std::to_string(result.beam_count_max);
  }
  std::string odometry = std::to_string(result.odometry_count) + " odometry";
  if (result.noisy_odometry) {
    odometry += " (noisy, seed " + std::to_string(*arguments.noise_seed) + ")";
  }
  std::printf("wrote %s: %llu scans (%s beams), %s, %.1f s%s\n", arguments.bag.c_str(),
              static_cast<unsigned long long>(result.scan_count), beams.c_str(), odometry.c_str(),
              result.duration_s, Skipped(result).c_str());
  if (!arguments.reference.empty()) {
    std::printf("wrote %s: %llu reference poses\n", arguments.reference.c_str(),
                static_cast<unsigned long long>(result.reference_poses));
  }
}

void RunTum(const TumArguments& arguments, CliContext& context) {
  importers::TumImportOptions options;
  options.reference_path = arguments.reference;
  if (!arguments.camera.empty()) {
    options.camera = importers::ParseTumCamera(arguments.camera);
    if (!options.camera) {
      throw UsageError("--camera: '" + arguments.camera + "' is not one of fr1, fr2, fr3");
    }
  }
  const importers::TumImportResult result =
      importers::ImportTumSequence(arguments.directory, arguments.bag, options, context.Progress());
  context.FinishProgress();
  for (const std::string& warning : result.warnings) context.Warn(warning);
  const auto pairs = static_cast<unsigned long long>(result.pairs_written);
  std::printf("wrote %s: %llu colour, %llu depth, %llu camera_info (%s%s), %.1f s\n",
              arguments.bag.c_str(), pairs, pairs, pairs, importers::TumCameraName(result.camera),
              result.camera_from_directory ? ", from the directory name" : "", result.duration_s);
  if (!arguments.reference.empty()) {
    std::printf("wrote %s: %llu reference poses\n", arguments.reference.c_str(),
                static_cast<unsigned long long>(result.reference_poses));
  }
}

void RegisterCarmen(CLI::App& import, CliContext& context) {
  auto arguments = std::make_shared<CarmenArguments>();
  CLI::App* carmen = context.AddCommand(
      import, "carmen",
      "Import a CARMEN laser log (plain or .gz): /scan, /odom and /tf_static (base_link -> laser)");
  carmen->add_option("LOG", arguments->log, "CARMEN log file, plain text or gzip")
      ->required()
      ->check(CLI::ExistingFile);
  carmen->add_option("-o,--output", arguments->bag, "Bag directory to create")->required();
  carmen->add_option("--reference", arguments->reference,
                     "Also write the log's (corrected) robot poses, one per scan, as a TUM "
                     "trajectory file");
  carmen
      ->add_option("--odometry-noise", arguments->noise_seed,
                   "Replace the odometry by the reference corrupted with seeded Gaussian noise "
                   "(5 % of distance for dx, dy; 5 % of turn + 1 deg/m + 0.1 deg for dtheta)")
      ->check(CLI::NonNegativeNumber);
  carmen->callback([arguments, &context] {
    context.run = [arguments, &context] { RunCarmen(*arguments, context); };
  });
}

void RegisterTum(CLI::App& import, CliContext& context) {
  auto arguments = std::make_shared<TumArguments>();
  CLI::App* tum = context.AddCommand(
      import, "tum",
      "Import a TUM RGB-D sequence directory (rgb.txt, depth.txt, rgb/, depth/): colour, "
      "depth in mm and camera_info");
  tum->add_option("DIR", arguments->directory, "TUM RGB-D sequence directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  tum->add_option("-o,--output", arguments->bag, "Bag directory to create")->required();
  tum->add_option("--reference", arguments->reference,
                  "Also write groundtruth.txt's poses as a TUM trajectory file");
  tum->add_option("--camera", arguments->camera,
                  "TUM camera calibration fr1|fr2|fr3 (default: from the directory name, e.g. "
                  "rgbd_dataset_freiburg2_desk)");
  tum->callback([arguments, &context] {
    context.run = [arguments, &context] { RunTum(*arguments, context); };
  });
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
