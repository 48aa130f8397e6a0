// littermap survey BAG --site SITE.gpkg [-o OUT] [--force]: reconstruct, detect, ingest, heatmap
// and report in one command, resuming where it stopped (reports/survey.hpp).

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "cli/sensor_arguments.hpp"
#include "db/site_locator.hpp"
#include "reports/survey.hpp"
#include "reports/survey_summary.hpp"

namespace littermap::cli {
namespace {

void RunSurvey(reports::SurveyOptions options, const std::string& site,
               const SensorArguments& sensors, CliContext& context) {
  options.site = db::ParseSiteLocator(site, "--site");
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
  const reports::SurveyResult result = reports::RunSurvey(options, callbacks);
  std::printf("%s", reports::SurveySummary(result.report, result.name, result.report_html).c_str());
}

}  // namespace

void RegisterSurveyCommand(CLI::App& app, CliContext& context) {
  auto options = std::make_shared<reports::SurveyOptions>();
  auto sensors = std::make_shared<SensorArguments>();
  auto site = std::make_shared<std::string>();
  CLI::App* command = context.AddCommand(
      app, "survey",
      "Reconstruct, detect, ingest, heatmap and report in one go, resuming where it stopped");
  command->add_option("BAG", options->bag, "Run bag directory")->required();
  command
      ->add_option("--site", *site,
                   "Site database, created when missing: SITE.gpkg, or "
                   "postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  command->add_option("-o,--output", options->output_dir,
                      "Output directory (default: NAME-survey in the current directory)");
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
  command->callback([options, site, sensors, &context] {
    context.run = [options, site, sensors, &context] {
      RunSurvey(*options, *site, *sensors, context);
    };
  });
}

}  // namespace littermap::cli
