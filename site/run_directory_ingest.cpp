#include "site/run_directory_ingest.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/pose3.hpp"
#include "core/text_file.hpp"
#include "reconstruct/map_registration.hpp"
#include "run/run_digest.hpp"
#include "run/run_files.hpp"
#include "run/run_name.hpp"

namespace littermap::site {
namespace {

std::vector<PlanarPose> PlanarTrajectory(const std::vector<StampedPose>& poses) {
  std::vector<PlanarPose> planar;
  planar.reserve(poses.size());
  for (const StampedPose& pose : poses) planar.push_back(PlanarPoseOf(pose));
  return planar;
}

// A survey covers a park, not a country: a position this far from the run's start is a unit or
// format error, and a coverage grid over it would not fit in memory.
constexpr double kMaxRunExtentM = 20000;

void CheckExtent(const std::filesystem::path& file, double x_m, double y_m, double from_x_m,
                 double from_y_m) {
  if (!(std::hypot(x_m - from_x_m, y_m - from_y_m) <= kMaxRunExtentM)) {
    char where[96];
    std::snprintf(where, sizeof where, "(%g, %g)", x_m, y_m);
    throw BadInputError(file.string() + ": a position at " + where +
                        " m lies more than 20 km from the run's start; a survey's trajectory "
                        "and items are in metres of the run's frame");
  }
}

// reconstruct's quality.json, checked to be JSON; empty when the run has none (a simulator truth
// directory).
std::string ReadQuality(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return {};
  std::string text = ReadTextFile(file);
  if (!nlohmann::json::accept(text)) {
    throw BadInputError(file.string() + ": not a JSON file (reconstruct writes it; rerun it)");
  }
  return text;
}

void CheckNameFree(db::SiteDatabase& site, const std::string& name, const std::string& digest) {
  for (const db::RunRecord& run : site.Runs()) {
    if (run.name == name && run.source_digest != digest) {
      throw BadInputError(site.name() + ": already holds a run named '" + name +
                          "' with other results (run " + std::to_string(run.run_id) +
                          "); the site keeps it. To add these results as another run, give "
                          "--name");
    }
  }
}

// Places the run (unless it is already in the site) and ingests it.
IngestResult PlaceAndIngest(db::SiteDatabase& site, const std::filesystem::path& map_yaml,
                            const RunDirectoryIngestOptions& options, const RunInput& run_frame,
                            std::vector<std::string>* notes) {
  for (int attempt = 0;; ++attempt) {
    RunInput run = run_frame;
    if (!site.FindRun(run.source_digest)) PlaceRun(site, map_yaml, options.placement, &run, notes);
    for (PlanarPose& pose : run.T_site_base) pose = Compose(run.T_site_run, pose);
    for (RunItem& item : run.items) {
      const Eigen::Vector2d p =
          reconstruct::Transform(run.T_site_run, Eigen::Vector2d(item.xy.x, item.xy.y));
      item.xy = {p.x(), p.y()};
    }
    try {
      return IngestRun(site, run, options.ingest);
    } catch (const SiteMapDefinedMeanwhile&) {
      if (attempt > 0) throw;
    }
  }
}

}  // namespace

RunDirectoryIngestResult IngestRunDirectory(db::SiteDatabase& site,
                                            const std::filesystem::path& run_dir,
                                            RunDirectoryIngestOptions options) {
  RunDirectoryIngestResult result;
  const run::RunDirectoryFiles files = run::FindRunDirectoryFiles(run_dir);
  const std::string name = run::RunName(options.name, run_dir);
  CheckNameFree(site, name, run::RunDigest(files));
  result.simulator_truth = files.simulator_truth;
  if (files.simulator_truth) {
    options.ingest.drop_unobserved_items = true;
    result.warnings.push_back(files.items.string() +
                              ": no items.csv; using the simulator's truth as the run's items "
                              "(only those inside the camera coverage)");
  }
  const std::vector<StampedPose> poses = bag::ReadTumTrajectory(files.trajectory);
  RunInput run;
  run.name = name;
  result.name = run.name;
  run.source_digest = run::RunDigest(files);
  run.T_site_base = PlanarTrajectory(poses);
  if (!poses.empty()) {
    run.start_time_s = ToSeconds(poses.front().stamp_ns);
    run.end_time_s = ToSeconds(poses.back().stamp_ns);
  }
  run.items = ReadRunItems(files.items);
  if (!run.T_site_base.empty()) {
    const PlanarPose& start = run.T_site_base.front();
    for (const PlanarPose& pose : run.T_site_base) {
      CheckExtent(files.trajectory, pose.x_m, pose.y_m, start.x_m, start.y_m);
    }
    for (const RunItem& item : run.items) {
      CheckExtent(files.items, item.xy.x, item.xy.y, start.x_m, start.y_m);
    }
  }
  const run::RunFiles run_files(run_dir);
  run.reconstruction_quality = ReadQuality(run_files.quality());
  result.ingest = PlaceAndIngest(site, run_files.map_yaml(), options, run, &result.notes);
  return result;
}

RunDirectoryIngestResult IngestRunDirectory(const db::SiteLocator& site_file,
                                            const std::filesystem::path& run_dir,
                                            RunDirectoryIngestOptions options) {
  db::SiteDatabase site = db::SiteDatabase::Open(site_file);
  return IngestRunDirectory(site, run_dir, std::move(options));
}

std::string IngestSummary(const RunDirectoryIngestResult& result, const std::string& site_name) {
  std::string text;
  for (const std::string& note : result.notes) text += note + "\n";
  const IngestResult& run = result.ingest;
  if (run.already_ingested) {
    return text + "Run " + result.name + " is already in " + site_name + " as run " +
           std::to_string(run.run_id) + "; nothing changed";
  }
  const auto s = [](std::size_t n) { return n == 1 ? "" : "s"; };
  char figures[256];
  std::snprintf(figures, sizeof figures,
                "': %zu pose%s, %.1f m driven, %.0f m2 observed, %zu detection%s (%zu new item%s, "
                "%zu seen again",
                run.poses, s(run.poses), run.length_m, run.observed_area_m2, run.detections,
                s(run.detections), run.new_items, s(run.new_items), run.items_seen_again);
  text += "Ingested run " + std::to_string(run.run_id) + " '" + result.name + figures;
  if (result.simulator_truth) {
    text += ", " + std::to_string(run.items_unobserved) + " outside the camera coverage skipped";
  }
  return text + ")";
}

}  // namespace littermap::site
