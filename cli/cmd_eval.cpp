// littermap eval trajectory EST.tum REF.tum [--json] [--max-time-difference S] [--rpe-delta M]
// ATE and RPE with the TUM benchmark's definitions (eval/trajectory_metrics.hpp).
// littermap eval detections ITEMS.csv TRUTH.csv [--natural NATURAL.csv]
//     [--visible VISIBLE.csv [--min-pixels N]] [--match-radius M] [--json]
// Litter precision, recall, per-class table and confusion (eval/detection_metrics.hpp).
// littermap eval map BAG TRAJECTORY.tum... [--cell-size M] [--max-range M] [--json]
// How sharp a map each trajectory draws from the bag's scans (eval/map_sharpness.hpp).
// littermap eval settle BAG TRAJECTORY.tum [-o SETTLED.tum] [--json]
// How far a trajectory lies from the nearest one its scans agree with
// (reconstruct/scan_settling.hpp).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "eval/detection_metrics.hpp"
#include "eval/map_sharpness.hpp"
#include "eval/trajectory_metrics.hpp"
#include "reconstruct/reconstruction.hpp"
#include "reconstruct/scan_settling.hpp"

namespace littermap::cli {
namespace {

struct TrajectoryArguments {
  std::string estimate;
  std::string reference;
  bool json = false;
  eval::TrajectoryMetricsOptions options;
};

std::vector<StampedPose> Load(const std::string& path) { return bag::ReadTumTrajectory(path); }

void RunTrajectory(const TrajectoryArguments& arguments) {
  const eval::TrajectoryMetrics metrics = eval::EvaluateTrajectory(
      Load(arguments.estimate), Load(arguments.reference), arguments.options);
  if (arguments.json) {
    nlohmann::ordered_json json;
    json["ate_rmse_m"] = metrics.ate_rmse_m;
    json["ate_mean_m"] = metrics.ate_mean_m;
    json["ate_max_m"] = metrics.ate_max_m;
    json["rpe_trans_mean_m"] = metrics.rpe_trans_mean_m;
    json["rpe_trans_rmse_m"] = metrics.rpe_trans_rmse_m;
    json["rpe_rot_mean_deg"] = metrics.rpe_rot_mean_deg;
    json["associated_poses"] = metrics.associated_poses;
    json["rpe_pairs"] = metrics.rpe_pairs;
    std::printf("%s\n", json.dump(2).c_str());
    return;
  }
  std::printf("associated poses   %zu\n", metrics.associated_poses);
  std::printf("ATE RMSE           %.4f m (mean %.4f m, max %.4f m)\n", metrics.ate_rmse_m,
              metrics.ate_mean_m, metrics.ate_max_m);
  std::printf("RPE translation    %.4f m mean, %.4f m RMSE over %zu pairs %.2f m apart\n",
              metrics.rpe_trans_mean_m, metrics.rpe_trans_rmse_m, metrics.rpe_pairs,
              arguments.options.rpe_delta_m);
  std::printf("RPE rotation       %.3f deg mean\n", metrics.rpe_rot_mean_deg);
}

struct BagScans {
  PlanarPose T_base_laser;
  std::vector<LaserScan> scans;
};

// A bag's laser extrinsic (warnings reported) and all its scans.
BagScans ReadBagScans(const std::string& bag, const std::string& scan_topic, CliContext& context) {
  reconstruct::ReconstructionOptions bag_options;
  bag_options.topics.scan = scan_topic;
  std::vector<std::string> warnings;
  BagScans read;
  read.T_base_laser = reconstruct::ReadLaserExtrinsic(bag, bag_options, &warnings);
  for (const std::string& warning : warnings) context.Warn(warning);
  context.Status("reading the scans of " + bag);
  read.scans = reconstruct::ReadScans(bag, scan_topic);
  return read;
}

struct MapArguments {
  std::string bag;
  std::vector<std::string> trajectories;
  std::string scan_topic = bag::RunTopics{}.scan;
  bool json = false;
  eval::MapSharpnessOptions options;
};

void RunMap(const MapArguments& arguments, CliContext& context) {
  arguments.options.Validate();
  const auto [T_base_laser, scans] = ReadBagScans(arguments.bag, arguments.scan_topic, context);
  std::vector<eval::MapSharpness> results;
  for (const std::string& path : arguments.trajectories) {
    context.Status("drawing the scans with " + path);
    const std::vector<StampedPose> trajectory = Load(path);
    eval::MapSharpness sharpness;
    try {
      sharpness = eval::MeasureMapSharpness(scans, T_base_laser, trajectory, arguments.options);
    } catch (const BadInputError& error) {
      throw BadInputError(path + ": " + error.what());
    }
    if (sharpness.scans_drawn < sharpness.scans) {
      char within[64];
      std::snprintf(within, sizeof within, "%g s", arguments.options.max_time_difference_s);
      context.Warn(path + ": " + std::to_string(sharpness.scans - sharpness.scans_drawn) + " of " +
                   std::to_string(sharpness.scans) + " scans have no pose within " + within +
                   " and are not drawn; counts of trajectories that draw different scans do "
                   "not compare");
    }
    results.push_back(sharpness);
  }
  context.FinishProgress();
  if (arguments.json) {
    nlohmann::ordered_json json;
    json["cell_size_m"] = arguments.options.cell_size_m;
    json["max_range_m"] = arguments.options.max_range_m;
    json["trajectories"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < results.size(); ++i) {
      json["trajectories"].push_back({{"trajectory", arguments.trajectories[i]},
                                      {"scans", results[i].scans},
                                      {"scans_drawn", results[i].scans_drawn},
                                      {"echoes_drawn", results[i].echoes_drawn},
                                      {"occupied_cells", results[i].occupied_cells}});
    }
    std::printf("%s\n", json.dump(2).c_str());
    return;
  }
  std::printf("occupied %.0f cm cells of the echoes within %.1f m (fewer: sharper map)\n",
              100 * arguments.options.cell_size_m, arguments.options.max_range_m);
  std::printf("%12s %9s %12s %12s  %s\n", "cells", "vs first", "echoes", "scans", "trajectory");
  for (std::size_t i = 0; i < results.size(); ++i) {
    std::printf("%12zu %8.1f%% %12zu %5zu/%-6zu  %s\n", results[i].occupied_cells,
                100.0 * static_cast<double>(results[i].occupied_cells) /
                    static_cast<double>(results.front().occupied_cells),
                results[i].echoes_drawn, results[i].scans_drawn, results[i].scans,
                arguments.trajectories[i].c_str());
  }
}

void RegisterMapCommand(CLI::App& eval_command, CliContext& context) {
  auto arguments = std::make_shared<MapArguments>();
  CLI::App* map = context.AddCommand(
      eval_command, "map",
      "How sharp a map each trajectory draws from the bag's scans: the number of grid cells their "
      "echoes occupy (fewer is sharper; needs no reference, so it also judges one)");
  map->add_option("BAG", arguments->bag, "Run bag with the laser scans")
      ->required()
      ->check(CLI::ExistingPath);
  map->add_option("TRAJECTORY", arguments->trajectories,
                  "Trajectories of base_link (TUM format), e.g. RUN_DIR/trajectory.tum and a "
                  "reference; the table compares each with the first")
      ->required()
      ->check(CLI::ExistingFile);
  map->add_option("--scan-topic", arguments->scan_topic, "LaserScan topic")->capture_default_str();
  map->add_option("--cell-size", arguments->options.cell_size_m, "Grid cell size, metres")
      ->capture_default_str();
  map->add_option("--max-range", arguments->options.max_range_m,
                  "Echoes further than this are not drawn, metres")
      ->capture_default_str();
  map->add_option("--max-time-difference", arguments->options.max_time_difference_s,
                  "Largest stamp difference between a scan and its pose, seconds")
      ->capture_default_str();
  map->add_flag("--json", arguments->json,
                "JSON output (per trajectory: occupied_cells, echoes_drawn, scans_drawn, scans)");
  map->callback([arguments, &context] {
    context.run = [arguments, &context] { RunMap(*arguments, context); };
  });
}

struct SettleArguments {
  std::string bag;
  std::string trajectory;
  std::string output;
  std::string scan_topic = bag::RunTopics{}.scan;
  double max_time_difference_s = 0.02;
  bool json = false;
  reconstruct::ScanSettlingOptions options;
};

std::vector<StampedPose> ToTum(const std::vector<std::pair<TimestampNs, PlanarPose>>& poses) {
  std::vector<StampedPose> tum;
  for (const auto& [stamp_ns, pose] : poses) tum.push_back(StampedPoseFromPlanar(stamp_ns, pose));
  return tum;
}

// The scans of the bag placed with the trajectory's poses and aligned; warnings for what was
// left out.
reconstruct::ScanSettling Settle(const SettleArguments& arguments, CliContext& context) {
  const auto [T_base_laser, scans] = ReadBagScans(arguments.bag, arguments.scan_topic, context);
  std::vector<TimestampNs> stamps_ns;
  for (const LaserScan& scan : scans) stamps_ns.push_back(scan.stamp_ns);
  const std::vector<std::optional<PlanarPose>> poses =
      eval::PlanarPosesAt(Load(arguments.trajectory), stamps_ns, arguments.max_time_difference_s);
  context.Status("aligning the scans from the poses of " + arguments.trajectory);
  reconstruct::ScanSettling settling;
  try {
    settling = reconstruct::SettleOnScans(scans, poses, T_base_laser, arguments.options);
  } catch (const BadInputError& error) {
    throw BadInputError(arguments.trajectory + ": " + error.what());
  }
  context.FinishProgress();
  if (settling.scans_posed < settling.scans) {
    context.Warn(std::to_string(settling.scans - settling.scans_posed) + " of " +
                 std::to_string(settling.scans) + " scans have no pose in " + arguments.trajectory +
                 " close enough in time, and are left out");
  }
  if (settling.scans_placed < settling.scans_posed) {
    context.Warn(std::to_string(settling.scans_posed - settling.scans_placed) + " of " +
                 std::to_string(settling.scans) +
                 " scans have too few valid echoes, and are left out");
  }
  if (!settling.alignment.usable) {
    context.Warn("the scan alignment stopped early (" + std::to_string(settling.alignment.rounds) +
                 " usable rounds); the settled poses are those of its last usable round");
  }
  return settling;
}

void RunSettle(const SettleArguments& arguments, CliContext& context) {
  arguments.options.Validate();
  if (!(arguments.max_time_difference_s >= 0)) {
    throw UsageError("--max-time-difference must be >= 0");
  }
  const std::filesystem::path output = arguments.output;
  if (!output.empty() &&
      !std::filesystem::is_directory(output.parent_path().empty() ? std::filesystem::path(".")
                                                                  : output.parent_path())) {
    throw UsageError(arguments.output + ": its directory does not exist");
  }
  const reconstruct::ScanSettling settling = Settle(arguments, context);
  const std::vector<StampedPose> settled = ToTum(settling.settled);
  const eval::TrajectoryMetrics moved =
      eval::EvaluateTrajectory(ToTum(settling.given), settled, {});
  if (!output.empty()) bag::WriteTumTrajectory(output, settled);
  if (arguments.json) {
    nlohmann::ordered_json json;
    json["scans"] = settling.scans;
    json["scans_posed"] = settling.scans_posed;
    json["scans_placed"] = settling.scans_placed;
    json["scans_aligned"] = settling.settled.size();
    json["scan_pairs"] = settling.alignment.pairs_matched;
    json["point_pairs"] = settling.alignment.correspondences;
    json["usable"] = settling.alignment.usable;
    json["ate_rmse_m"] = moved.ate_rmse_m;
    json["ate_max_m"] = moved.ate_max_m;
    json["rpe_trans_mean_m"] = moved.rpe_trans_mean_m;
    json["rpe_rot_mean_deg"] = moved.rpe_rot_mean_deg;
    std::printf("%s\n", json.dump(2).c_str());
    return;
  }
  std::printf("scans aligned      %zu of %zu (one per %.2f m or %.0f deg of motion)\n",
              settling.settled.size(), settling.scans, arguments.options.frame_spacing_m,
              arguments.options.frame_spacing_rad * 180 / std::numbers::pi);
  std::printf("pairs              %zu scan pairs, %zu point pairs\n",
              settling.alignment.pairs_matched, settling.alignment.correspondences);
  std::printf("moved to agree with its scans:\n");
  std::printf("ATE RMSE           %.4f m (max %.4f m)\n", moved.ate_rmse_m, moved.ate_max_m);
  std::printf("RPE translation    %.4f m mean over %zu pairs 1 m apart\n", moved.rpe_trans_mean_m,
              moved.rpe_pairs);
  std::printf("RPE rotation       %.3f deg mean\n", moved.rpe_rot_mean_deg);
}

void RegisterSettleCommand(CLI::App& eval_command, CliContext& context) {
  auto arguments = std::make_shared<SettleArguments>();
  CLI::App* settle = context.AddCommand(
      eval_command, "settle",
      "How far a trajectory lies from the nearest one its own scans agree with: the scans are "
      "aligned against each other from its poses (reconstruct's final scan alignment), and the "
      "move is reported as ATE and RPE (needs no reference, so it also judges one)");
  settle->add_option("BAG", arguments->bag, "Run bag with the laser scans")
      ->required()
      ->check(CLI::ExistingPath);
  settle->add_option("TRAJECTORY", arguments->trajectory, "Trajectory of base_link (TUM format)")
      ->required()
      ->check(CLI::ExistingFile);
  settle->add_option("-o,--output", arguments->output,
                     "Write the settled poses (TUM format) of the scans aligned (one per 0.5 m or "
                     "17 deg of motion)");
  settle->add_option("--scan-topic", arguments->scan_topic, "LaserScan topic")
      ->capture_default_str();
  settle
      ->add_option("--max-time-difference", arguments->max_time_difference_s,
                   "Largest stamp difference between a scan and its pose, seconds")
      ->capture_default_str();
  settle->add_flag("--json", arguments->json,
                   "JSON output (ate_rmse_m, rpe_trans_mean_m, rpe_rot_mean_deg of the move, "
                   "scans_aligned, ...)");
  settle->callback([arguments, &context] {
    context.run = [arguments, &context] { RunSettle(*arguments, context); };
  });
}

struct DetectionArguments {
  std::string items;
  std::string truth;
  std::string natural;
  std::string visible;
  std::vector<std::string> align;  // EST.tum REF.tum
  bool json = false;
  eval::DetectionMetricsOptions options;
};

// Items of a run placed in its own map frame, carried into the truth's frame by the rigid
// alignment of the run's trajectory onto the reference (the one ATE uses).
std::vector<eval::DetectedItem> AlignItems(std::vector<eval::DetectedItem> items,
                                           const std::vector<std::string>& align) {
  if (align.empty()) return items;
  const eval::TrajectoryMetrics metrics =
      eval::EvaluateTrajectory(Load(align[0]), Load(align[1]), eval::TrajectoryMetricsOptions{});
  for (auto& item : items) {
    const Eigen::Vector3d p =
        metrics.T_reference_estimate * Eigen::Vector3d(item.position_m.x(), item.position_m.y(), 0);
    item.position_m = p.head<2>();
  }
  return items;
}

nlohmann::ordered_json DetectionJson(const eval::DetectionMetrics& metrics,
                                     const eval::DetectionMetricsOptions& options) {
  nlohmann::ordered_json json;
  json["precision"] = metrics.precision;
  json["recall"] = metrics.recall;
  json["f1"] = metrics.f1;
  json["true_positives"] = metrics.true_positives;
  json["false_positives"] = metrics.false_positives;
  json["false_negatives"] = metrics.false_negatives;
  json["class_accuracy"] = metrics.class_accuracy;
  json["litter_natural_accuracy"] = metrics.litter_natural_accuracy;
  json["litter_natural_pairs"] = metrics.litter_natural_pairs;
  json["truth_litter"] = metrics.truth_litter;
  json["detected_litter"] = metrics.detected_litter;
  json["ignored_detections"] = metrics.ignored_detections;
  json["hidden_truth"] = metrics.hidden_truth;
  json["per_class"] = nlohmann::ordered_json::object();
  for (const eval::ClassMetrics& c : metrics.per_class) {
    json["per_class"][c.class_name] = {{"truth", c.truth},
                                       {"detected", c.detected},
                                       {"tp", c.true_positives},
                                       {"precision", c.precision},
                                       {"recall", c.recall}};
  }
  json["confusion"] = nlohmann::ordered_json::object();
  const auto& labels = metrics.confusion_labels;
  for (std::size_t t = 0; t < labels.size(); ++t) {
    nlohmann::ordered_json row = nlohmann::ordered_json::object();
    for (std::size_t p = 0; p < labels.size(); ++p) row[labels[p]] = metrics.confusion[t][p];
    json["confusion"][labels[t]] = row;
  }
  json["match_radius_m"] = options.match_radius_m;
  return json;
}

void PrintDetectionTables(const eval::DetectionMetrics& metrics) {
  std::printf("\n%-16s %6s %9s %5s %10s %7s\n", "class", "truth", "detected", "tp", "precision",
              "recall");
  for (const eval::ClassMetrics& c : metrics.per_class) {
    std::printf("%-16s %6zu %9zu %5zu %10.3f %7.3f\n", c.class_name.c_str(), c.truth, c.detected,
                c.true_positives, c.precision, c.recall);
  }
  std::printf("\nconfusion (rows: truth, columns: predicted)\n%-16s", "");
  const auto& labels = metrics.confusion_labels;
  for (const std::string& label : labels) {
    std::printf(" %*s", static_cast<int>(std::max<std::size_t>(label.size(), 4)), label.c_str());
  }
  for (std::size_t t = 0; t < labels.size(); ++t) {
    std::printf("\n%-16s", labels[t].c_str());
    for (std::size_t p = 0; p < labels.size(); ++p) {
      std::printf(" %*zu", static_cast<int>(std::max<std::size_t>(labels[p].size(), 4)),
                  metrics.confusion[t][p]);
    }
  }
  std::printf("\n");
}

void RunDetections(const DetectionArguments& arguments) {
  std::vector<eval::TruthObject> truth = eval::ReadTruthObjects(arguments.truth, true);
  if (!arguments.natural.empty()) {
    const auto natural = eval::ReadTruthObjects(arguments.natural, false);
    truth.insert(truth.end(), natural.begin(), natural.end());
  }
  std::optional<eval::VisiblePixels> visible;
  if (!arguments.visible.empty()) visible = eval::ReadVisiblePixels(arguments.visible);
  const eval::DetectionMetrics metrics = eval::EvaluateDetections(
      AlignItems(eval::ReadDetectedItems(arguments.items), arguments.align), truth,
      arguments.options, visible);
  if (arguments.json) {
    std::printf("%s\n", DetectionJson(metrics, arguments.options).dump(2).c_str());
    return;
  }
  std::printf("matching           one-to-one within %.2f m, nearest pairs first\n",
              arguments.options.match_radius_m);
  std::printf("truth litter       %zu\n", metrics.truth_litter);
  if (visible) {
    std::printf("hidden objects     %zu (under %zu pixels in every mask: not truth)\n",
                metrics.hidden_truth, arguments.options.min_visible_pixels);
  }
  std::printf("detected litter    %zu\n", metrics.detected_litter);
  if (metrics.ignored_detections > 0) {
    std::printf("ignored detections %zu (at hidden litter, not scored)\n",
                metrics.ignored_detections);
  }
  std::printf("true positives     %zu\n", metrics.true_positives);
  std::printf("false positives    %zu\n", metrics.false_positives);
  std::printf("false negatives    %zu\n", metrics.false_negatives);
  std::printf("precision          %.3f\n", metrics.precision);
  std::printf("recall             %.3f\n", metrics.recall);
  std::printf("F1                 %.3f\n", metrics.f1);
  std::printf("class accuracy     %.3f over %zu true positives\n", metrics.class_accuracy,
              metrics.true_positives);
  std::printf("litter/natural     %.3f over %zu matched pairs of all items\n",
              metrics.litter_natural_accuracy, metrics.litter_natural_pairs);
  PrintDetectionTables(metrics);
}

void RegisterDetectionsCommand(CLI::App& eval_command, CliContext& context) {
  auto arguments = std::make_shared<DetectionArguments>();
  CLI::App* detections = context.AddCommand(
      eval_command, "detections",
      "Litter precision, recall and F1, a per-class table and a confusion matrix of detected "
      "items against the simulator's truth, matched one-to-one within a radius");
  // No ExistingFile checks: an unreadable file is bad input (exit 2) and the readers say so.
  detections->add_option("ITEMS", arguments->items, "Detected items (items.csv)")->required();
  detections->add_option("TRUTH", arguments->truth, "Truth litter (the simulator's litter.csv)")
      ->required();
  detections->add_option("--natural", arguments->natural,
                         "Natural look-alikes (the simulator's natural.csv), for the confusion "
                         "matrix and litter/natural accuracy");
  CLI::Option* visible = detections->add_option(
      "--visible", arguments->visible,
      "The simulator's masks/visible.csv: only objects shown with --min-pixels count as truth");
  detections
      ->add_option("--min-pixels", arguments->options.min_visible_pixels,
                   "Pixels an object must cover in some masked frame to count as truth")
      ->capture_default_str()
      ->needs(visible);
  detections
      ->add_option("--match-radius", arguments->options.match_radius_m,
                   "Largest distance of a matched item and truth object, metres")
      ->capture_default_str();
  detections
      ->add_option("--align", arguments->align,
                   "EST.tum REF.tum: carry the items into the truth's frame by the rigid alignment "
                   "of the run's trajectory onto the reference trajectory (as ATE aligns them)")
      ->expected(2);
  detections->add_flag("--json", arguments->json,
                       "JSON output (precision, recall, f1, per_class, confusion, ...)");
  detections->callback(
      [arguments, &context] { context.run = [arguments] { RunDetections(*arguments); }; });
}

}  // namespace

void RegisterEvalCommands(CLI::App& app, CliContext& context) {
  CLI::App* eval_command = context.AddCommand(
      app, "eval", "Evaluate trajectories and litter detections against ground truth");
  eval_command->require_subcommand(1);
  auto arguments = std::make_shared<TrajectoryArguments>();
  CLI::App* trajectory = context.AddCommand(
      *eval_command, "trajectory",
      "ATE RMSE after rigid (Horn) alignment and RPE over pairs 1 m apart, as the TUM RGB-D "
      "benchmark scripts compute them");
  trajectory->add_option("EST", arguments->estimate, "Estimated trajectory (TUM format)")
      ->required()
      ->check(CLI::ExistingFile);
  trajectory->add_option("REF", arguments->reference, "Reference trajectory (TUM format)")
      ->required()
      ->check(CLI::ExistingFile);
  trajectory->add_flag("--json", arguments->json,
                       "JSON output (ate_rmse_m, rpe_trans_mean_m, rpe_rot_mean_deg, ...)");
  trajectory
      ->add_option("--max-time-difference", arguments->options.max_time_difference_s,
                   "Largest stamp difference of an associated pair, seconds")
      ->capture_default_str();
  trajectory
      ->add_option("--rpe-delta", arguments->options.rpe_delta_m,
                   "Distance travelled between the poses of an RPE pair, metres")
      ->capture_default_str();
  trajectory->callback(
      [arguments, &context] { context.run = [arguments] { RunTrajectory(*arguments); }; });
  RegisterDetectionsCommand(*eval_command, context);
  RegisterMapCommand(*eval_command, context);
  RegisterSettleCommand(*eval_command, context);
}

}  // namespace littermap::cli
