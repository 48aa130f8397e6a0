#include "detect/item_fusion.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace littermap::detect {

void FusionOptions::Validate() const {
  if (!(association_radius_m > 0)) throw UsageError("detect: association_radius_m must be > 0");
  if (min_views < 1) throw UsageError("detect: min_views must be >= 1");
  if (!(min_seen_share >= 0 && min_seen_share <= 1)) {
    throw UsageError("detect: min_seen_share must be in [0, 1]");
  }
  if (class_views < 0) throw UsageError("detect: class_views must be >= 0");
  if (!(min_litter_probability > 0 && min_litter_probability <= 1)) {
    throw UsageError("detect: min_litter_probability must be in (0, 1]");
  }
}

ItemFusion::ItemFusion(FusionOptions options, std::size_t classes)
    : options_(options), classes_(classes) {
  options_.Validate();
}

void ItemFusion::KeepIfAmongTheLargest(Track& track, const Sighting& sighting) const {
  auto& kept = track.class_views;
  if (options_.class_views == 0 || kept.size() < static_cast<std::size_t>(options_.class_views)) {
    kept.emplace_back(sighting.pixels, sighting.class_probabilities);
    return;
  }
  // Replace the smallest (the first of equals) when this sighting is larger.
  const auto smallest = std::min_element(
      kept.begin(), kept.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (sighting.pixels > smallest->first) {
    smallest->first = sighting.pixels;
    smallest->second = sighting.class_probabilities;
  }
}

int ItemFusion::Add(const Sighting& sighting) {
  if (sighting.class_probabilities.size() != classes_) {
    throw InternalError("detect: sighting has " +
                        std::to_string(sighting.class_probabilities.size()) +
                        " class probabilities, the classifier " + std::to_string(classes_));
  }
  std::size_t best = tracks_.size();
  double best_distance = options_.association_radius_m;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const double distance =
        (tracks_[i].mean().head<2>() - sighting.position_world_m.head<2>()).norm();
    if (distance <= best_distance) {
      best_distance = distance;
      best = i;
    }
  }
  if (best == tracks_.size()) {
    Track track;
    track.first_seen_ns = sighting.stamp_ns;
    tracks_.push_back(std::move(track));
  }
  Track& track = tracks_[best];
  // Inverse-variance weights: depth noise grows with range squared, so its variance with the 4th
  // power; the position error of a blob centroid grows more gently, so range squared is used.
  const double weight = 1.0 / std::max(0.25, sighting.range_m * sighting.range_m);
  track.weighted_sum += weight * sighting.position_world_m;
  track.weight += weight;
  track.size_sum += sighting.size_m;
  KeepIfAmongTheLargest(track, sighting);
  ++track.views;
  track.last_frame = sighting.frame;
  track.first_seen_ns = std::min(track.first_seen_ns, sighting.stamp_ns);
  track.last_seen_ns = std::max(track.last_seen_ns, sighting.stamp_ns);
  return static_cast<int>(best) + 1;
}

void ItemFusion::Observe(std::size_t frame,
                         const std::function<bool(const Eigen::Vector3d&, double)>& could_see) {
  for (Track& track : tracks_) {
    if (track.last_frame != frame && could_see(track.mean(), track.size_sum / track.views)) {
      ++track.missed_views;
    }
  }
}

bool ItemFusion::SeldomSeen(const Track& track) const {
  return track.views < options_.min_seen_share * (track.views + track.missed_views);
}

std::size_t ItemFusion::seldom_seen() const {
  return static_cast<std::size_t>(std::count_if(
      tracks_.begin(), tracks_.end(),
      [&](const Track& t) { return t.views >= options_.min_views && SeldomSeen(t); }));
}

std::vector<LitterItem> ItemFusion::Items() const {
  std::vector<LitterItem> items;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const Track& track = tracks_[i];
    if (track.views < options_.min_views || SeldomSeen(track)) continue;
    LitterItem item;
    item.id = static_cast<int>(i) + 1;
    item.position_world_m = track.mean();
    item.size_m = track.size_sum / track.views;
    item.views = track.views;
    item.missed_views = track.missed_views;
    item.first_seen_ns = track.first_seen_ns;
    item.last_seen_ns = track.last_seen_ns;
    item.class_probabilities.assign(classes_, 0.0);
    for (const auto& [pixels, probabilities] : track.class_views) {
      for (std::size_t k = 0; k < classes_; ++k) item.class_probabilities[k] += probabilities[k];
    }
    for (double& p : item.class_probabilities) p /= static_cast<double>(track.class_views.size());
    item.best_class = static_cast<std::size_t>(
        std::max_element(item.class_probabilities.begin(), item.class_probabilities.end()) -
        item.class_probabilities.begin());
    item.confidence = item.class_probabilities[item.best_class];
    items.push_back(std::move(item));
  }
  return items;
}

}  // namespace littermap::detect
