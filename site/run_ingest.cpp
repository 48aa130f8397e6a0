#include "site/run_ingest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <set>
#include <unordered_map>

#include "core/error.hpp"

namespace littermap::site {
namespace {

// Known items by coarse cell, to find those within the radius of an observation.
class ItemIndex {
 public:
  ItemIndex(std::vector<db::ItemRecord> items, double radius_m)
      : items_(std::move(items)), radius_m_(radius_m) {
    for (std::size_t i = 0; i < items_.size(); ++i)
      cells_[Key(items_[i].site_xy, 0, 0)].push_back(i);
  }

  struct Candidate {
    double distance_m;
    std::size_t run_item;
    std::int64_t fid;
  };

  // Every known item within the radius of the run's item.
  void AddCandidates(const RunItem& item, std::size_t run_item,
                     std::vector<Candidate>& candidates) const {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto cell = cells_.find(Key(item.xy, dx, dy));
        if (cell == cells_.end()) continue;
        for (std::size_t i : cell->second) {
          const db::ItemRecord& known = items_[i];
          const double d = std::hypot(known.site_xy.x - item.xy.x, known.site_xy.y - item.xy.y);
          if (d <= radius_m_) candidates.push_back({d, run_item, known.fid});
        }
      }
    }
  }

 private:
  std::int64_t Key(const db::PointXY& p, int dx, int dy) const {
    const auto cx = static_cast<std::int64_t>(std::floor(p.x / radius_m_)) + dx;
    const auto cy = static_cast<std::int64_t>(std::floor(p.y / radius_m_)) + dy;
    return cx * 73856093 ^ cy * 19349663;
  }
  std::vector<db::ItemRecord> items_;
  double radius_m_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

// The run's trajectory in the site CRS (heading turned by the site rotation).
std::vector<PlanarPose> ToCrs(const db::SiteFrame& frame, std::span<const PlanarPose> poses) {
  const double rotation = frame.rotation_deg * std::numbers::pi / 180.0;
  std::vector<PlanarPose> out;
  out.reserve(poses.size());
  for (const PlanarPose& p : poses) {
    const db::PointXY xy = frame.ToCrs({p.x_m, p.y_m});
    out.push_back({xy.x, xy.y, WrapAngle(p.theta_rad + rotation)});
  }
  return out;
}

db::CoverageRecord Coverage(std::span<const PlanarPose> crs_poses, const IngestOptions& options) {
  double min_x = crs_poses[0].x_m, max_x = min_x, min_y = crs_poses[0].y_m, max_y = min_y;
  for (const PlanarPose& p : crs_poses) {
    min_x = std::min(min_x, p.x_m);
    max_x = std::max(max_x, p.x_m);
    min_y = std::min(min_y, p.y_m);
    max_y = std::max(max_y, p.y_m);
  }
  const CameraFootprintOptions& camera = options.camera;
  const double reach = GroundSector(camera).far_m + std::hypot(camera.mount_x_m, camera.mount_y_m);
  const heatmap::GridGeometry grid = heatmap::GridGeometry::Covering(
      min_x, min_y, max_x, max_y, options.coverage_cell_size_m, reach + 1.0);
  RunCoverage run = CoverRun(grid, crs_poses, camera);
  db::CoverageRecord record;
  record.cell_size_m = grid.cell_size_m;
  record.min_x_m = grid.min_x_m;
  record.max_y_m = grid.max_y_m;
  record.width = grid.width;
  record.height = grid.height;
  record.observed_area_m2 = run.observed_area_m2;
  record.observed = std::move(run.observed);
  return record;
}

double PathLength(std::span<const PlanarPose> poses) {
  double length = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    length += std::hypot(poses[i].x_m - poses[i - 1].x_m, poses[i].y_m - poses[i - 1].y_m);
  }
  return length;
}

// Items of this run are matched one-to-one against the items known before it, nearest pairs
// first: two items of one run are two items (the detect stage has already fused its views),
// however close. The class plays no part: the classifier may call one crumpled cup a carton in
// another run, and litter stays where it lies; the site's item keeps the class it was first
// found with, each detection keeps its own.
void StoreItems(db::SiteDatabase& site, const RunInput& run, const IngestOptions& options,
                const db::CoverageRecord& coverage, IngestResult& result) {
  std::vector<bool> observed(run.items.size(), true);
  if (options.drop_unobserved_items) {
    for (std::size_t i = 0; i < run.items.size(); ++i) {
      observed[i] = coverage.Covers(site.site().frame.ToCrs(run.items[i].xy));
      result.items_unobserved += !observed[i];
    }
  }
  // Only the known items within reach of this run's: a site holds a city park's years.
  std::vector<db::PointXY> places;
  for (std::size_t i = 0; i < run.items.size(); ++i) {
    if (observed[i]) places.push_back(run.items[i].xy);
  }
  db::Envelope reach = db::EnvelopeOf(places);
  reach.min_x -= options.same_item_radius_m;
  reach.max_x += options.same_item_radius_m;
  reach.min_y -= options.same_item_radius_m;
  reach.max_y += options.same_item_radius_m;
  const ItemIndex known(places.empty() ? std::vector<db::ItemRecord>{} : site.ItemsWithin(reach),
                        options.same_item_radius_m);
  std::vector<ItemIndex::Candidate> candidates;
  for (std::size_t i = 0; i < run.items.size(); ++i) {
    if (observed[i]) known.AddCandidates(run.items[i], i, candidates);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.distance_m < b.distance_m; });
  std::vector<std::optional<std::int64_t>> match(run.items.size());
  std::set<std::int64_t> taken;
  for (const ItemIndex::Candidate& c : candidates) {
    if (match[c.run_item] || taken.count(c.fid)) continue;
    match[c.run_item] = c.fid;
    taken.insert(c.fid);
  }
  for (std::size_t i = 0; i < run.items.size(); ++i) {
    if (!observed[i]) continue;
    const RunItem& item = run.items[i];
    std::optional<std::int64_t> fid = match[i];
    if (fid) {
      site.MarkItemSeen(*fid, result.run_id);
      ++result.items_seen_again;
    } else {
      fid = site.AddItem({0, item.class_name, item.xy, item.z_m, item.size_m, item.confidence,
                          result.run_id, result.run_id, 1});
      ++result.new_items;
    }
    site.AddDetection({result.run_id, fid, item.id, item.class_name, item.xy, item.z_m, item.size_m,
                       item.confidence});
    ++result.detections;
  }
}

}  // namespace

IngestResult IngestRun(db::SiteDatabase& site, const RunInput& run, const IngestOptions& options) {
  if (!(options.coverage_cell_size_m > 0.0) || !(options.same_item_radius_m > 0.0)) {
    throw UsageError("ingest: the coverage cell size and the same-item radius must be > 0 m");
  }
  if (run.T_site_base.size() < 2) {
    throw BadInputError("run " + run.name + ": the trajectory has fewer than two poses");
  }
  IngestResult result;
  result.poses = run.T_site_base.size();
  result.length_m = PathLength(run.T_site_base);
  // The expensive part outside the transaction, so a concurrent ingest waits less.
  const std::vector<PlanarPose> crs_poses = ToCrs(site.site().frame, run.T_site_base);
  db::CoverageRecord coverage = Coverage(crs_poses, options);
  result.observed_area_m2 = coverage.observed_area_m2;
  std::vector<db::PointXY> track;
  track.reserve(run.T_site_base.size());
  for (const PlanarPose& p : run.T_site_base) track.push_back({p.x_m, p.y_m});

  const IngestResult before_transaction = result;
  site.InTransaction([&] {
    result = before_transaction;  // run again after a conflict: from scratch
    if (const auto existing = site.FindRun(run.source_digest)) {
      result.already_ingested = true;
      result.run_id = *existing;
      return;
    }
    result.run_id = site.AddRun({0, run.name, run.source_digest, run.start_time_s, run.end_time_s,
                                 result.length_m, run.T_site_run, run.registration_quality,
                                 run.reconstruction_quality});
    if (run.site_map && site.SiteMap()) {
      throw SiteMapDefinedMeanwhile(site.name() + ": another run defined the site map meanwhile");
    }
    if (run.site_map) {
      db::SiteMapRecord map = *run.site_map;
      map.run_id = result.run_id;
      site.SetSiteMap(map);
    }
    site.AddRunTrack(result.run_id, track);
    coverage.run_id = result.run_id;
    site.AddCoverage(coverage);
    StoreItems(site, run, options, coverage, result);
  });
  return result;
}

}  // namespace littermap::site
