// littermap survey BAG --site SITE.gpkg [-o OUT] [--force]: the main job in one command.
// reconstruct -> detect -> ingest -> heatmap -> report, each stage the function the subcommand
// of the same name runs with its defaults (cli/run_stages.hpp), into
//   OUT/run/      trajectory, map, quality, items and detections of the run
//   OUT/maps/     density and effort GeoTIFFs, density.png, hotspots and items as CSV/GeoJSON
//   OUT/report/   index.html and report.json of the whole site
// Resumable: reconstruct and detect are skipped when they finished before and their outputs
// are newer than their inputs (OUT/.stages/STAGE.done marks a finished stage, so a stage cut
// short is redone). Ingest is idempotent; heatmap and report always run, as other runs may have
// reached the site since. A failing stage is named and the earlier stages' outputs stay.

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/report_command.hpp"
#include "cli/run_stages.hpp"
#include "core/error.hpp"
#include "db/site_database.hpp"
#include "reports/report_files.hpp"
#include "reports/survey_summary.hpp"
#include "run/run_digest.hpp"
#include "run/run_files.hpp"
#include "run/stage_marker.hpp"

namespace littermap::cli {
namespace {

namespace fs = std::filesystem;

struct SurveyArguments {
  std::string bag;
  std::string site;
  std::string output;
  std::string name;
  std::string model;
  int every = 0;  // 0: detect's default
  bool force = false;
};

struct Stage {
  std::string name;
  run::StageFiles files;
  std::function<void()> run;
};

db::SiteDatabase OpenOrCreateSite(const SurveyArguments& arguments) {
  if (fs::exists(arguments.site)) return db::SiteDatabase::Open(arguments.site);
  db::SiteOptions options;
  options.name = fs::path(arguments.site).stem().string();
  db::SiteDatabase site = db::SiteDatabase::Create(arguments.site, options);
  std::printf(
      "Created site '%s' in %s: local frame, positions in metres from the dock (for GPS "
      "coordinates create the site first with 'littermap site init --crs')\n",
      options.name.c_str(), arguments.site.c_str());
  return site;
}

// The run must not already be in the site with other results under the same name: the site
// would count its litter twice.
void CheckNotIngestedDifferently(const SurveyArguments& arguments, const fs::path& run_dir,
                                 const std::string& name) {
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const std::string digest = run::RunDigest(run::FindRunDirectoryFiles(run_dir));
  for (const db::RunRecord& run : site.Runs()) {
    if (run.name == name && run.source_digest != digest) {
      throw BadInputError(arguments.site + ": already holds a run named '" + name +
                          "' with other results (run " + std::to_string(run.run_id) +
                          "); the site keeps it. To add these results as another run, give "
                          "--name");
    }
  }
}

void RunSurvey(const SurveyArguments& arguments, CliContext& context) {
  const fs::path bag = arguments.bag;
  if (!fs::is_directory(bag)) throw UsageError(arguments.bag + ": not a run bag directory");
  const std::string name = arguments.name.empty()
                               ? fs::absolute(bag).lexically_normal().filename().string()
                               : arguments.name;
  const fs::path out =
      arguments.output.empty() ? fs::path(name + "-survey") : fs::path(arguments.output);
  const fs::path run_dir = out / "run", maps_dir = out / "maps", report_dir = out / "report";
  const fs::path stages_dir = out / ".stages";
  fs::create_directories(stages_dir);
  OpenOrCreateSite(arguments);  // before any long stage: a bad site fails fast

  const std::vector<fs::path> bag_files = run::FilesIn(bag);
  const std::string model = arguments.model.empty() ? LITTERMAP_DEFAULT_MODEL : arguments.model;
  const run::RunFiles files(run_dir);
  std::vector<fs::path> detect_inputs = bag_files;
  detect_inputs.push_back(files.trajectory());
  detect_inputs.push_back(model);
  run::DetectRunOptions detect;
  detect.model = model;
  if (arguments.every > 0) detect.objects.every = static_cast<std::size_t>(arguments.every);
  reports::SiteReport report;
  const std::vector<Stage> stages = {
      {"reconstruct",
       {bag_files, {files.trajectory(), files.map_yaml(), files.map_pgm(), files.quality()}},
       [&] { ReconstructStage(bag, run_dir, {}, context); }},
      {"detect",
       {detect_inputs, {files.items(), files.detections()}},
       [&] { DetectStage(bag, run_dir, detect, context); }},
      {"ingest",
       {},
       [&] {
         CheckNotIngestedDifferently(arguments, run_dir, name);
         IngestStage(arguments.site, run_dir, name, context);
       }},
      {"heatmap", {}, [&] { HeatmapStage(arguments.site, maps_dir, context); }},
      {"report",
       {},
       [&] {
         db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
         report = reports::WriteReportFiles(site, report_dir, DefaultReportOptions());
         std::printf("wrote %s and report.json\n", (report_dir / "index.html").c_str());
       }},
  };

  for (std::size_t i = 0; i < stages.size(); ++i) {
    const Stage& stage = stages[i];
    const std::string label =
        "[" + std::to_string(i + 1) + "/" + std::to_string(stages.size()) + " " + stage.name + "]";
    const fs::path marker = stages_dir / (stage.name + ".done");
    if (!arguments.force && run::StageUpToDate(stage.files, marker)) {
      std::printf("%s up to date (outputs newer than inputs), skipped; --force redoes it\n",
                  label.c_str());
      continue;
    }
    std::printf("%s\n", label.c_str());
    std::fflush(stdout);
    fs::remove(marker);
    context.task_prefix = label + " ";
    try {
      stage.run();
    } catch (const std::exception& e) {
      context.task_prefix.clear();
      const auto* error = dynamic_cast<const Error*>(&e);
      throw Error(error ? error->kind() : ErrorKind::kInternal,
                  "survey stage '" + stage.name + "' failed: " + e.what() +
                      "\n  the earlier stages' outputs are kept in " + out.string() +
                      "; once fixed, the same command resumes at this stage");
    }
    context.FinishProgress();
    context.task_prefix.clear();
    std::ofstream(marker) << stage.name << " finished\n";
  }
  std::printf("%s", reports::SurveySummary(report, name, report_dir / "index.html").c_str());
}

}  // namespace

void RegisterSurveyCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<SurveyArguments>();
  CLI::App* command = context.AddCommand(
      app, "survey",
      "Reconstruct, detect, ingest, heatmap and report in one go, resuming where it stopped");
  command->add_option("BAG", arguments->bag, "Run bag directory")->required();
  command->add_option("--site", arguments->site, "Site database (created when missing)")
      ->required();
  command->add_option("-o,--output", arguments->output,
                      "Output directory (default: NAME-survey in the current directory)");
  command->add_option("--name", arguments->name, "Run name (default: the bag directory's name)");
  command->add_option("--model", arguments->model, "Classifier model (default: the built-in one)");
  command->add_option("--every", arguments->every, "Detect in every n-th camera frame only")
      ->check(CLI::PositiveNumber);
  command->add_flag("--force", arguments->force, "Redo every stage, even if up to date");
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunSurvey(*arguments, context); };
  });
}

}  // namespace littermap::cli
