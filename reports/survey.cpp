#include "reports/survey.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/failure.hpp"
#include "core/output_file.hpp"
#include "db/site_database.hpp"
#include "heatmap/heatmap_files.hpp"
#include "reports/report_files.hpp"
#include "run/reconstruct_run.hpp"
#include "run/run_files.hpp"
#include "run/run_name.hpp"
#include "run/run_start.hpp"
#include "run/stage_marker.hpp"
#include "site/run_directory_ingest.hpp"

namespace littermap::reports {
namespace {

namespace fs = std::filesystem;

struct Stage {
  std::string name;
  run::StageFiles files;
  std::function<void(const ProgressCallback& progress)> run;
};

// The survey's directories and what the stages share.
struct Survey {
  Survey(const SurveyOptions& survey_options, const SurveyCallbacks& survey_callbacks)
      : options(survey_options), callbacks(survey_callbacks) {}

  const SurveyOptions& options;
  const SurveyCallbacks& callbacks;
  std::string name;
  fs::path out, run_dir, maps_dir, report_dir, stages_dir;
  SiteReport report;

  void Print(const std::string& text) const {
    if (callbacks.print) callbacks.print(text);
  }
  void Warn(const std::vector<std::string>& warnings) const {
    if (!callbacks.warn) return;
    for (const std::string& warning : warnings) callbacks.warn(warning);
  }
};

heatmap::HeatmapFilesOptions HeatmapOptions(const Survey& survey) {
  heatmap::HeatmapFilesOptions options;
  options.hotspots.min_items = survey.options.hotspot_min_items;
  return options;
}

// Before any long stage: a bad site fails fast.
void OpenOrCreateSite(const Survey& survey) {
  const db::SiteLocator& where = survey.options.site;
  if (db::SiteDatabase::Exists(where)) {
    db::SiteDatabase::Open(where);
    return;
  }
  db::SiteOptions site;
  site.name = where.postgres() ? where.schema : where.file.stem().string();
  db::SiteDatabase::Create(where, site);
  survey.Print("Created site '" + site.name + "' in " + where.display +
               ": local frame, positions in metres from the dock (for GPS coordinates create "
               "the site first with 'littermap site init --crs')");
}

std::vector<Stage> Stages(Survey& survey) {
  const SurveyOptions& options = survey.options;
  const std::vector<fs::path> bag_files = run::FilesIn(options.bag);
  const run::RunFiles files(survey.run_dir);
  std::vector<fs::path> detect_inputs = bag_files;
  detect_inputs.push_back(files.trajectory());
  detect_inputs.push_back(options.detect.model);
  const auto reconstruct = [&survey](const ProgressCallback& progress) {
    const run::ReconstructRunResult result = run::ReconstructRun(
        survey.options.bag, survey.run_dir, survey.options.reconstruct, progress);
    survey.Warn(result.warnings);
    survey.Print(run::ReconstructSummary(result));
  };
  const auto detect = [&survey](const ProgressCallback& progress) {
    const run::DetectRunResult result =
        run::DetectRun(survey.options.bag, survey.run_dir, survey.options.detect, progress);
    survey.Warn(result.warnings);
    survey.Print(run::DetectSummary(result, survey.options.detect.fusion));
  };
  const auto ingest = [&survey](const ProgressCallback&) {
    site::RunDirectoryIngestOptions run;
    run.name = survey.name;
    const site::RunDirectoryIngestResult result =
        site::IngestRunDirectory(survey.options.site, survey.run_dir, run);
    survey.Warn(result.warnings);
    survey.Print(site::IngestSummary(result, survey.options.site.display));
  };
  const auto heatmap = [&survey](const ProgressCallback&) {
    const heatmap::HeatmapFilesResult result =
        heatmap::WriteHeatmapFiles(survey.options.site, survey.maps_dir, HeatmapOptions(survey));
    survey.Warn(result.warnings);
    survey.Print(heatmap::HeatmapSummary(result, survey.maps_dir));
  };
  const auto report = [&survey](const ProgressCallback&) {
    ReportFilesOptions outputs;
    StampReportFilesOptions(outputs);
    outputs.figures.hotspot_min_items = survey.options.hotspot_min_items;
    survey.report = WriteReportFiles(survey.options.site, survey.report_dir, outputs);
    survey.Print("wrote " + (survey.report_dir / "index.html").string() + " and report.json");
  };
  return {
      {"reconstruct",
       {bag_files, {files.trajectory(), files.map_yaml(), files.map_pgm(), files.quality()}},
       reconstruct},
      {"detect", {detect_inputs, {files.items(), files.detections()}}, detect},
      {"ingest", {}, ingest},
      {"heatmap", {}, heatmap},
      {"report", {}, report},
  };
}

ProgressCallback Prefixed(const ProgressCallback& progress, const std::string& prefix) {
  if (!progress) return {};
  return [progress, prefix](const Progress& update) {
    const std::string task = prefix + std::string(update.task);
    Progress prefixed = update;
    prefixed.task = task;
    progress(prefixed);
  };
}

void RunStage(const Survey& survey, const Stage& stage, const std::string& label) {
  const fs::path marker = survey.stages_dir / (stage.name + ".done");
  if (!survey.options.force && run::StageUpToDate(stage.files, marker)) {
    survey.Print(label + " up to date (outputs newer than inputs), skipped; --force redoes it");
    return;
  }
  survey.Print(label);
  fs::remove(marker);
  try {
    stage.run(Prefixed(survey.callbacks.progress, label + " "));
  } catch (const std::exception& e) {
    throw Error(KindOf(e), "survey stage '" + stage.name + "' failed: " + e.what() +
                               "\n  the earlier stages' outputs are kept in " +
                               survey.out.string() +
                               "; once fixed, the same command resumes at this stage");
  }
  WriteFileAtomically(marker, stage.name + " finished\n");
}

}  // namespace

namespace {

// The survey's directories, named after the run; checks the bag.
std::unique_ptr<Survey> PrepareSurvey(const SurveyOptions& options,
                                      const SurveyCallbacks& callbacks) {
  std::error_code error;
  if (!fs::exists(options.bag, error)) throw FileFailure(options.bag, "cannot read", ENOENT);
  if (!fs::is_directory(options.bag, error)) {
    throw BadInputError(options.bag.string() + ": not a run bag directory");
  }
  auto survey = std::make_unique<Survey>(options, callbacks);
  survey->name = run::RunName(options.name, options.bag);
  survey->out =
      options.output_dir.empty() ? fs::path(survey->name + "-survey") : options.output_dir;
  survey->run_dir = survey->out / "run";
  survey->maps_dir = survey->out / "maps";
  survey->report_dir = survey->out / "report";
  survey->stages_dir = survey->out / ".stages";
  return survey;
}

// Stages [first, last) of the survey.
void RunStages(Survey& survey, std::size_t first, std::size_t last) {
  fs::create_directories(survey.stages_dir);
  const std::vector<Stage> stages = Stages(survey);
  for (std::size_t i = first; i < last; ++i) {
    RunStage(survey, stages[i],
             "[" + std::to_string(i + 1) + "/" + std::to_string(stages.size()) + " " +
                 stages[i].name + "]");
  }
}

constexpr std::size_t kIngestStage = 2;  // reconstruct, detect | ingest, heatmap, report
constexpr std::size_t kStageCount = 5;

SurveyResult ResultOf(Survey& survey) {
  return {survey.name, survey.out, survey.report_dir / "index.html", std::move(survey.report)};
}

// The callbacks of one run among several: its name before every line, one call at a time.
SurveyCallbacks RunCallbacks(const SurveyCallbacks& callbacks, const std::string& name,
                             std::mutex& mutex) {
  const std::string prefix = "[" + name + "] ";
  SurveyCallbacks run;
  if (callbacks.progress) {
    run.progress = Prefixed(
        [&callbacks, &mutex](const Progress& update) {
          const std::lock_guard lock(mutex);
          callbacks.progress(update);
        },
        prefix);
  }
  if (callbacks.print) {
    run.print = [&callbacks, &mutex, prefix](const std::string& text) {
      const std::lock_guard lock(mutex);
      callbacks.print(prefix + text);
    };
  }
  if (callbacks.warn) {
    run.warn = [&callbacks, &mutex, prefix](const std::string& message) {
      const std::lock_guard lock(mutex);
      callbacks.warn(prefix + message);
    };
  }
  return run;
}

}  // namespace

SurveyResult RunSurvey(const SurveyOptions& options, const SurveyCallbacks& callbacks) {
  const std::unique_ptr<Survey> survey = PrepareSurvey(options, callbacks);
  fs::create_directories(survey->stages_dir);
  OpenOrCreateSite(*survey);
  RunStages(*survey, 0, kStageCount);
  return ResultOf(*survey);
}

std::vector<SurveyResult> RunSurveys(const std::vector<SurveyOptions>& runs, int jobs,
                                     const SurveyCallbacks& callbacks) {
  if (jobs < 1) throw UsageError("survey: -j must be at least 1");
  if (runs.empty()) return {};
  std::mutex mutex;
  std::vector<SurveyCallbacks> run_callbacks;
  std::vector<std::unique_ptr<Survey>> surveys;
  std::set<std::string> names, outputs;
  for (const SurveyOptions& options : runs) {
    if (options.site.display != runs.front().site.display) {
      throw UsageError("survey: the runs go to different sites (" + runs.front().site.display +
                       ", " + options.site.display + "); survey each site on its own");
    }
    run_callbacks.push_back(
        RunCallbacks(callbacks, run::RunName(options.name, options.bag), mutex));
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    surveys.push_back(PrepareSurvey(runs[i], run_callbacks[i]));
    const Survey& survey = *surveys.back();
    if (!names.insert(survey.name).second) {
      throw UsageError("survey: two runs are named '" + survey.name +
                       "'; give the bags distinct folder names");
    }
    if (!outputs.insert(fs::weakly_canonical(survey.out).string()).second) {
      throw UsageError("survey: two runs would write to " + survey.out.string());
    }
  }
  OpenOrCreateSite(*surveys.front());

  // Reconstruct and detect, `jobs` runs at a time; a run's failure is kept for the end.
  std::vector<std::string> failures(surveys.size());
  std::vector<ErrorKind> kinds(surveys.size(), ErrorKind::kInternal);
  const auto fail = [&](std::size_t i, const std::exception& e) {
    failures[i] = surveys[i]->name + ": " + e.what();
    kinds[i] = KindOf(e);
  };
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < surveys.size(); i = next++) {
      try {
        RunStages(*surveys[i], 0, kIngestStage);
      } catch (const std::exception& e) {
        fail(i, e);
      }
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::min<int>(jobs, static_cast<int>(surveys.size())); ++t) {
    threads.emplace_back(worker);
  }
  worker();
  for (std::thread& thread : threads) thread.join();

  // Ingest, heatmap and report in start-time order.
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < surveys.size(); ++i) {
    if (!failures[i].empty()) continue;
    try {
      order.emplace_back(run::RunStartTimeS(surveys[i]->run_dir), i);
    } catch (const std::exception& e) {
      fail(i, e);
    }
  }
  std::stable_sort(order.begin(), order.end());
  std::vector<SurveyResult> results;
  for (const auto& [start, i] : order) {
    try {
      RunStages(*surveys[i], kIngestStage, kStageCount);
      results.push_back(ResultOf(*surveys[i]));
    } catch (const std::exception& e) {
      fail(i, e);
    }
  }
  std::string message;
  std::optional<ErrorKind> kind;
  for (std::size_t i = 0; i < surveys.size(); ++i) {
    if (failures[i].empty()) continue;
    if (!kind) kind = kinds[i];
    message += (message.empty() ? "" : "\n") + failures[i];
  }
  if (kind) {
    throw Error(*kind, std::to_string(surveys.size() - results.size()) + " of " +
                           std::to_string(surveys.size()) +
                           " runs failed (the others finished):\n" + message);
  }
  return results;
}

}  // namespace littermap::reports
