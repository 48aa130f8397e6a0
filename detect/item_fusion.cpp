#include "detect/item_fusion.hpp"

#include <algorithm>
#include <iterator>
#include <numeric>

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

void ItemFusion::KeepIfAmongTheLargest(Track& track, int pixels,
                                       const std::vector<double>& classes) const {
  auto& kept = track.class_views;
  if (options_.class_views == 0 || kept.size() < static_cast<std::size_t>(options_.class_views)) {
    kept.emplace_back(pixels, classes);
    return;
  }
  // Replace the smallest (the first of equals) when this sighting is larger.
  const auto smallest = std::min_element(
      kept.begin(), kept.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (pixels > smallest->first) {
    smallest->first = pixels;
    smallest->second = classes;
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
  KeepIfAmongTheLargest(track, sighting.pixels, sighting.class_probabilities);
  ++track.views;
  if (track.seen_frames.empty() || track.seen_frames.back() != sighting.frame) {
    track.seen_frames.push_back(sighting.frame);
  }
  track.first_seen_ns = std::min(track.first_seen_ns, sighting.stamp_ns);
  track.last_seen_ns = std::max(track.last_seen_ns, sighting.stamp_ns);
  return static_cast<int>(best) + 1;
}

void ItemFusion::Observe(std::size_t frame,
                         const std::function<bool(const Eigen::Vector3d&, double)>& could_see) {
  for (Track& track : tracks_) {
    const bool seen = !track.seen_frames.empty() && track.seen_frames.back() == frame;
    if (!seen && could_see(track.mean(), track.size_sum / track.views)) {
      track.missed_frames.push_back(frame);
    }
  }
}

bool ItemFusion::SeldomSeen(const Track& track) const {
  const double chances = static_cast<double>(track.views + track.missed_frames.size());
  return track.views < options_.min_seen_share * chances;
}

void ItemFusion::Merge(Track& into, const Track& from) const {
  into.weighted_sum += from.weighted_sum;
  into.weight += from.weight;
  into.size_sum += from.size_sum;
  into.views += from.views;
  for (const auto& [pixels, classes] : from.class_views) {
    KeepIfAmongTheLargest(into, pixels, classes);
  }
  std::vector<std::size_t> seen, missed, missed_unseen;
  std::set_union(into.seen_frames.begin(), into.seen_frames.end(), from.seen_frames.begin(),
                 from.seen_frames.end(), std::back_inserter(seen));
  std::set_union(into.missed_frames.begin(), into.missed_frames.end(), from.missed_frames.begin(),
                 from.missed_frames.end(), std::back_inserter(missed));
  // A frame that missed one of the two but saw the other saw the merged item.
  std::set_difference(missed.begin(), missed.end(), seen.begin(), seen.end(),
                      std::back_inserter(missed_unseen));
  into.seen_frames = std::move(seen);
  into.missed_frames = std::move(missed_unseen);
  into.first_seen_ns = std::min(into.first_seen_ns, from.first_seen_ns);
  into.last_seen_ns = std::max(into.last_seen_ns, from.last_seen_ns);
}

std::vector<double> ItemFusion::ClassProbabilities(const Track& track) const {
  std::vector<double> mean(classes_, 0.0);
  for (const auto& [pixels, probabilities] : track.class_views) {
    for (std::size_t k = 0; k < classes_; ++k) mean[k] += probabilities[k];
  }
  for (double& p : mean) p /= static_cast<double>(track.class_views.size());
  return mean;
}

std::size_t ItemFusion::Likeliest(const std::vector<double>& probabilities) {
  return static_cast<std::size_t>(std::max_element(probabilities.begin(), probabilities.end()) -
                                  probabilities.begin());
}

LitterItem ItemFusion::MakeItem(const Track& track, int id) const {
  LitterItem item;
  item.id = id;
  item.position_world_m = track.mean();
  item.size_m = track.size_sum / track.views;
  item.views = track.views;
  item.missed_views = static_cast<int>(track.missed_frames.size());
  item.first_seen_ns = track.first_seen_ns;
  item.last_seen_ns = track.last_seen_ns;
  item.class_probabilities = ClassProbabilities(track);
  item.best_class = Likeliest(item.class_probabilities);
  item.confidence = item.class_probabilities[item.best_class];
  return item;
}

FusedItems ItemFusion::Fuse() const {
  FusedItems fused;
  std::vector<Track> tracks = tracks_;
  std::vector<bool> merged(tracks.size(), false);
  fused.item_of_candidate.resize(tracks.size());
  std::iota(fused.item_of_candidate.begin(), fused.item_of_candidate.end(), 1);
  const double radius = options_.association_radius_m;
  std::vector<Eigen::Vector2d> at(tracks.size());
  std::vector<std::size_t> kind(tracks.size());  // the likeliest class
  const auto describe = [&](std::size_t i) {
    at[i] = tracks[i].mean().head<2>();
    kind[i] = Likeliest(ClassProbabilities(tracks[i]));
  };
  for (std::size_t i = 0; i < tracks.size(); ++i) describe(i);
  while (true) {
    // The closest pair within the radius, found by a sweep over the candidates sorted by x.
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < tracks.size(); ++i) {
      if (!merged[i]) order.push_back(i);
    }
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return at[a].x() < at[b].x(); });
    double closest = radius;
    std::size_t keep = 0, absorb = 0;
    bool found = false;
    for (std::size_t i = 0; i < order.size(); ++i) {
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        if (at[order[j]].x() - at[order[i]].x() > radius) break;
        const double distance = (at[order[i]] - at[order[j]]).norm();
        if (distance <= closest && kind[order[i]] == kind[order[j]]) {
          closest = distance;
          keep = std::min(order[i], order[j]);
          absorb = std::max(order[i], order[j]);
          found = true;
        }
      }
    }
    if (!found) break;
    Merge(tracks[keep], tracks[absorb]);
    describe(keep);
    merged[absorb] = true;
    ++fused.merged;
    for (int& item : fused.item_of_candidate) {
      if (item == static_cast<int>(absorb) + 1) item = static_cast<int>(keep) + 1;
    }
  }
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const Track& track = tracks[i];
    if (merged[i] || track.views < options_.min_views) continue;
    if (SeldomSeen(track)) {
      ++fused.seldom_seen;
      continue;
    }
    fused.items.push_back(MakeItem(track, static_cast<int>(i) + 1));
  }
  return fused;
}

}  // namespace littermap::detect
