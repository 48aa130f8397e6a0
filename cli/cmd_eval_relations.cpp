// littermap eval relations: Kuemmerle et al.'s relations metric (eval/pose_relations.hpp)

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "core/error.hpp"
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

std::vector<double> ScanStamps(const RelationsArguments& arguments, CliContext& context) {
  if (!arguments.scanmap.empty()) return eval::ReadScanMapStamps(arguments.scanmap);
  context.Status("reading the scans of " + arguments.log);
  const importers::CarmenLog log = importers::ReadCarmenLog(arguments.log, context.Progress());
  context.FinishProgress();
  std::vector<double> stamps;
  for (const importers::CarmenLaserRecord& scan : log.scans) stamps.push_back(scan.timestamp_s);
  return stamps;
}

void RunRelations(const RelationsArguments& arguments, CliContext& context) {
  const std::vector<eval::PoseRelation> relations = eval::ReadPoseRelations(arguments.relations);
  const std::vector<double> stamps = ScanStamps(arguments, context);
  const eval::PoseRelationMetrics metrics =
      eval::EvaluatePoseRelations(arguments.trajectory, stamps, relations, arguments.options);
  std::printf("%s\n", arguments.json ? eval::ToJson(metrics).c_str()
                                     : eval::ToText(metrics, arguments.options).c_str());
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
      ->capture_default_str()
      ->check(FiniteRange(0, 3600));
  command
      ->add_option("--large-error", arguments->options.large_error_m,
                   "Relations with a larger translational error are counted, metres")
      ->capture_default_str()
      ->check(FiniteRange(0, 1e5));
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
