#pragma once
// `littermap survey` as a library call: one run bag through every stage, each with the defaults
// of the command of the same name,
//   reconstruct -> detect -> ingest -> heatmap -> report
// into
//   OUT/run/      trajectory, map, quality, items and detections of the run
//   OUT/maps/     density and effort GeoTIFFs, density.png, hotspots and items as CSV/GeoJSON
//   OUT/report/   index.html and report.json of the whole site
// The site is created (in a local frame) when missing. Resumable: reconstruct and detect are
// skipped when they finished before and their outputs are newer than their inputs
// (OUT/.stages/STAGE.done marks a finished stage, run/stage_marker.hpp, so a stage cut short is
// redone). Ingest is idempotent, and refuses results other than the ones the site holds under
// the run's name; heatmap and report always run, as other runs may have reached the site since.
// A failing stage is named and the earlier stages' outputs stay.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "db/site_locator.hpp"
#include "reports/site_report.hpp"
#include "run/detect_run.hpp"
#include "run/reconstruct_run.hpp"

namespace littermap::reports {

struct SurveyOptions {
  std::filesystem::path bag;
  db::SiteLocator site;              // created when missing
  std::filesystem::path output_dir;  // empty: NAME-survey in the current directory
  std::string name;                  // of the run in the site; empty: the bag directory's name
  run::ReconstructRunOptions reconstruct;
  run::DetectRunOptions detect;  // the model at least
  bool force = false;            // redo every stage, even if up to date
  int hotspot_min_items = heatmap::HotspotOptions{}.min_items;  // of the heatmap and the report
};

// How the survey tells what it does; each may be empty.
struct SurveyCallbacks {
  // Stage by stage: the tasks are put after the stage's label, e.g. "[2/5 detect] ".
  ProgressCallback progress;
  // Lines for the user (which stage runs or is skipped and what each stage came to), without the
  // final newline.
  std::function<void(const std::string& text)> print;
  std::function<void(const std::string& message)> warn;
};

struct SurveyResult {
  std::string name;  // of the run in the site
  std::filesystem::path output_dir;
  std::filesystem::path report_html;  // OUT/report/index.html
  SiteReport report;                  // of the whole site (reports/survey_summary.hpp)
};

// Throws UsageError when the bag is not a directory; Error of the failing stage's kind naming
// the stage and the output directory.
SurveyResult RunSurvey(const SurveyOptions& options, const SurveyCallbacks& callbacks);

// Several runs of one site: reconstruct and detect `jobs` runs at a time, then ingest, heatmap
// and report each run in the order the runs started (the earliest first, whatever order the
// bags were given in), so the site and each run's report are what surveying them one by one in
// time order gives. Every line and progress report names its run ("[NAME] "), and callbacks are
// called from one thread at a time. A run that fails does not stop the others: they finish (their
// outputs and reports stay on disk), then an Error naming each failed run and its stage is
// thrown, of the first failure's kind. Throws UsageError when the runs do not share one site or
// two share a name or an output directory, or jobs < 1.
std::vector<SurveyResult> RunSurveys(const std::vector<SurveyOptions>& runs, int jobs,
                                     const SurveyCallbacks& callbacks);

}  // namespace littermap::reports
