// littermap eval relations TRAJ.tum LOG.relations (--scanmap LOG.scanmap | --log LOG) [--json]
// The relations metric of Kuemmerle et al. 2009 (eval/pose_relations.hpp): a trajectory of one
// pose per scan graded by the benchmark's manually verified relative motions. The scans' stamps
// in the relations' time base come from a .scanmap (a re-stamped, thinned log such as
// ../shared/datasets/carmen/*-corrected) or from the raw CARMEN log itself.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "core/pose3.hpp"
#include "eval/pose_relations.hpp"
#include "importers/carmen_log.hpp"

namespace littermap::cli {
namespace {

struct RelationsArguments {
  std::string trajectory;
  std::string relations;
  std::string scanmap;
  std::string log;
  bool json = false;
  eval::PoseRelationOptions options;
};

nlohmann::ordered_json StatisticsJson(const eval::ErrorStatistics& s) {
  return {{"mean", s.mean}, {"stddev", s.stddev}, {"max", s.max}};
}

nlohmann::ordered_json ErrorsJson(const eval::RelationErrors& e) {
  return {{"trans_m", StatisticsJson(e.translation_m)},
          {"trans_sq_m2", StatisticsJson(e.translation_sq_m2)},
          {"rot_deg", StatisticsJson(e.rotation_deg)},
          {"rot_sq_deg2", StatisticsJson(e.rotation_sq_deg2)},
          {"trans_median_m", e.translation_median_m},
          {"over_large_error", e.over_large_error}};
}

void PrintErrors(const char* name, const eval::RelationErrors& e, double large_error_m) {
  std::printf("%s\n", name);
  std::printf("  translation      %.4f +- %.4f m (median %.4f m, max %.3f m, %zu over %.2f m)\n",
              e.translation_m.mean, e.translation_m.stddev, e.translation_median_m,
              e.translation_m.max, e.over_large_error, large_error_m);
  std::printf("  translation^2    %.5f +- %.5f m^2\n", e.translation_sq_m2.mean,
              e.translation_sq_m2.stddev);
  std::printf("  rotation         %.3f +- %.3f deg (max %.2f deg)\n", e.rotation_deg.mean,
              e.rotation_deg.stddev, e.rotation_deg.max);
  std::printf("  rotation^2       %.3f +- %.3f deg^2\n", e.rotation_sq_deg2.mean,
              e.rotation_sq_deg2.stddev);
}

std::vector<double> ScanStamps(const RelationsArguments& arguments, CliContext& context) {
  if (!arguments.scanmap.empty()) return eval::ReadScanMapStamps(arguments.scanmap);
  context.Status("reading the scans of " + arguments.log);
  const importers::CarmenLog log = importers::ReadCarmenLog(arguments.log, context.Progress());
  context.FinishProgress();
  std::vector<double> stamps;
  stamps.reserve(log.scans.size());
  for (const importers::CarmenLaserRecord& scan : log.scans) stamps.push_back(scan.timestamp_s);
  return stamps;
}

void RunRelations(const RelationsArguments& arguments, CliContext& context) {
  const std::vector<eval::PoseRelation> relations = eval::ReadPoseRelations(arguments.relations);
  const std::vector<double> stamps = ScanStamps(arguments, context);
  std::vector<PlanarPose> trajectory;
  for (const StampedPose& pose : bag::ReadTumTrajectory(arguments.trajectory)) {
    trajectory.push_back(PlanarPoseOf(pose));
  }
  eval::PoseRelationMetrics metrics;
  try {
    metrics = eval::EvaluatePoseRelations(trajectory, stamps, relations, arguments.options);
  } catch (const BadInputError& error) {
    throw BadInputError(arguments.trajectory + ": " + error.what());
  }
  if (arguments.json) {
    nlohmann::ordered_json json;
    json["relations"] = metrics.relations;
    json["used"] = metrics.used;
    json["unmatched"] = metrics.unmatched;
    json["metric_evaluator"] = ErrorsJson(metrics.component);
    json["cartographer"] = ErrorsJson(metrics.cartographer);
    std::printf("%s\n", json.dump(2).c_str());
    return;
  }
  std::printf("relations          %zu used of %zu (%zu with an end at no scan)\n", metrics.used,
              metrics.relations, metrics.unmatched);
  PrintErrors("metricEvaluator (component difference)", metrics.component,
              arguments.options.large_error_m);
  PrintErrors("Cartographer (est * inv(relation))", metrics.cartographer,
              arguments.options.large_error_m);
}

}  // namespace

void RegisterEvalRelationsCommand(CLI::App& app, CliContext& context) {
  CLI::App* eval_command = app.get_subcommand("eval");
  auto arguments = std::make_shared<RelationsArguments>();
  CLI::App* command = context.AddCommand(
      *eval_command, "relations",
      "Relative-motion errors against manually verified relations (Kuemmerle et al. 2009), "
      "with the benchmark's and Cartographer's definitions");
  // No ExistingFile checks: an unreadable file is bad input (exit 2) and the readers say so.
  command->add_option("TRAJ", arguments->trajectory, "One pose per scan (TUM format)")->required();
  command->add_option("RELATIONS", arguments->relations, "The log's .relations file")->required();
  CLI::Option* scanmap =
      command->add_option("--scanmap", arguments->scanmap,
                          "The scans' stamps in the relations' time base, for a re-stamped log");
  CLI::Option* log = command->add_option("--log", arguments->log,
                                         "The raw CARMEN log whose own stamps the relations use");
  scanmap->excludes(log);
  command
      ->add_option("--max-stamp-difference", arguments->options.max_stamp_difference_s,
                   "Largest difference of a relation stamp and its scan's, seconds")
      ->capture_default_str();
  command
      ->add_option("--large-error", arguments->options.large_error_m,
                   "Relations with a larger translational error are counted, metres")
      ->capture_default_str();
  command->add_flag("--json", arguments->json,
                    "JSON output (used, metric_evaluator.trans_m.mean, cartographer, ...)");
  command->callback([arguments, &context, scanmap, log] {
    if (scanmap->count() + log->count() == 0) {
      throw CLI::ValidationError("relations", "one of --scanmap and --log is required");
    }
    context.run = [arguments, &context] { RunRelations(*arguments, context); };
  });
}

}  // namespace littermap::cli
