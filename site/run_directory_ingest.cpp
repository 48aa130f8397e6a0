#include "site/run_directory_ingest.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/pose3.hpp"
#include "reconstruct/map_registration.hpp"
#include "run/run_digest.hpp"
#include "run/run_files.hpp"

namespace littermap::site {
namespace {

std::vector<PlanarPose> PlanarTrajectory(const std::vector<StampedPose>& poses) {
  std::vector<PlanarPose> planar;
  planar.reserve(poses.size());
  for (const StampedPose& pose : poses) planar.push_back(PlanarPoseOf(pose));
  return planar;
}

// reconstruct's quality.json, checked to be JSON; empty when the run has none (a simulator truth
// directory).
std::string ReadQuality(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return {};
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  if (!in || !nlohmann::json::accept(text.str())) {
    throw BadInputError(file.string() + ": not a JSON file (reconstruct writes it; rerun it)");
  }
  return text.str();
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
  result.simulator_truth = files.simulator_truth;
  if (files.simulator_truth) {
    options.ingest.drop_unobserved_items = true;
    result.warnings.push_back(files.items.string() +
                              ": no items.csv; using the simulator's truth as the run's items "
                              "(only those inside the camera coverage)");
  }
  const std::vector<StampedPose> poses = bag::ReadTumTrajectory(files.trajectory);
  RunInput run;
  run.name =
      options.name.empty() ? std::filesystem::absolute(run_dir).filename().string() : options.name;
  result.name = run.name;
  run.source_digest = run::RunDigest(files);
  run.T_site_base = PlanarTrajectory(poses);
  if (!poses.empty()) {
    run.start_time_s = ToSeconds(poses.front().stamp_ns);
    run.end_time_s = ToSeconds(poses.back().stamp_ns);
  }
  run.items = ReadRunItems(files.items);
  const run::RunFiles run_files(run_dir);
  run.reconstruction_quality = ReadQuality(run_files.quality());
  result.ingest = PlaceAndIngest(site, run_files.map_yaml(), options, run, &result.notes);
  return result;
}

}  // namespace littermap::site
