// littermap survey BAG... --site SITE [-o OUT] [-j N] [--force]: reconstruct, detect, ingest,
// heatmap and report in one command, resuming where it stopped, for one run or several side by
// side (reports/survey.hpp).

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "cli/sensor_arguments.hpp"
#include "db/site_locator.hpp"
#include "reports/survey.hpp"
#include "reports/survey_summary.hpp"
#include "run/run_name.hpp"

namespace littermap::cli {
namespace {

struct SurveyArguments {
  std::vector<std::string> bags;
  std::string site;
  int jobs = 1;
};

void RunSurvey(reports::SurveyOptions options, const SurveyArguments& arguments,
               const SensorArguments& sensors, CliContext& context) {
  options.site = db::ParseSiteLocator(arguments.site, "--site");
  if (options.detect.model.empty()) options.detect.model = LITTERMAP_DEFAULT_MODEL;
  options.reconstruct.topic_roles = options.detect.topic_roles = sensors.Roles();
  options.reconstruct.reconstruction.stamps = options.detect.objects.frames.stamps =
      sensors.Stamps();
  reports::SurveyCallbacks callbacks;
  callbacks.progress = context.Progress();
  callbacks.warn = [&context](const std::string& message) { context.Warn(message); };
  callbacks.print = [&context](const std::string& text) {
    context.FinishProgress();
    std::printf("%s\n", text.c_str());
    std::fflush(stdout);
  };
  if (arguments.bags.size() == 1) {
    options.bag = arguments.bags.front();
    const reports::SurveyResult result = reports::RunSurvey(options, callbacks);
    std::printf("%s",
                reports::SurveySummary(result.report, result.name, result.report_html).c_str());
    return;
  }
  if (!options.name.empty()) {
    throw UsageError("survey: --name names one run; several bags take their folders' names");
  }
  // Several runs: -o is the folder of their output folders, one per run, named after it.
  std::vector<reports::SurveyOptions> runs;
  for (const std::string& bag : arguments.bags) {
    reports::SurveyOptions run = options;
    run.bag = bag;
    if (!options.output_dir.empty()) {
      run.output_dir = options.output_dir / run::RunName({}, run.bag);
    }
    runs.push_back(std::move(run));
  }
  const std::vector<reports::SurveyResult> results =
      reports::RunSurveys(runs, arguments.jobs, callbacks);
  for (const reports::SurveyResult& result : results) {
    std::printf("%s",
                reports::SurveySummary(result.report, result.name, result.report_html).c_str());
  }
}

}  // namespace

void RegisterSurveyCommand(CLI::App& app, CliContext& context) {
  auto options = std::make_shared<reports::SurveyOptions>();
  auto sensors = std::make_shared<SensorArguments>();
  auto arguments = std::make_shared<SurveyArguments>();
  CLI::App* command = context.AddCommand(
      app, "survey",
      "Reconstruct, detect, ingest, heatmap and report in one go, resuming where it stopped");
  command
      ->add_option("BAG", arguments->bags,
                   "Run bag directories (several: surveyed side by side, added to the site in "
                   "the order they started)")
      ->required();
  command
      ->add_option("--site", arguments->site,
                   "Site database, created when missing: SITE.gpkg, or "
                   "postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  command->add_option("-o,--output", options->output_dir,
                      "Output directory (default: NAME-survey in the current directory); with "
                      "several bags, the directory of one NAME folder per run");
  command->add_option("-j,--jobs", arguments->jobs, "Runs reconstructed and detected at a time")
      ->capture_default_str()
      ->check(WholeNumber(1, 64));
  command->add_option(
      "--name", options->name,
      "Run name (default: the bag folder's name, or its parent's for a folder called bag)");
  command->add_option("--model", options->detect.model,
                      "Classifier model (default: the built-in one)");
  command
      ->add_option("--every", options->detect.objects.every,
                   "Detect in every n-th camera frame only")
      ->check(WholeNumber<std::size_t>(1, kMaxFrameStep));
  command
      ->add_option("--hotspot-min-items", options->hotspot_min_items,
                   "Distinct items a place needs to be called a hotspot")
      ->capture_default_str()
      ->check(WholeNumber(1, kMaxHotspotMinItems));
  command->add_flag("--force", options->force, "Redo every stage, even if up to date");
  AddSensorOptions(command, *sensors);
  command->callback([options, arguments, sensors, &context] {
    context.run = [options, arguments, sensors, &context] {
      RunSurvey(*options, *arguments, *sensors, context);
    };
  });
}

}  // namespace littermap::cli
