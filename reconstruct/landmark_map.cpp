#include "reconstruct/landmark_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "core/error.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

void LandmarkMapOptions::Validate() const {
  if (!(association_gate_m > 0) || !(radius_gate_m > 0) || !(active_path_m > 0)) {
    throw UsageError("landmarks: association gates and active_path_m must be > 0");
  }
  if (!(max_graph_radius_spread_m >= 0)) {
    throw UsageError("landmarks: max_graph_radius_spread_m must be >= 0");
  }
  if (!(local_path_m > 0) || !(min_loop_path_m > 0) || !(max_search_range_m > 0) ||
      !(pair_tolerance_m > 0) || !(min_pair_distance_m >= 0) || !(inlier_gate_m > 0) ||
      min_inliers < 3 || !(min_inlier_spread_m >= 0) || !(distinct_transform_m > 0) ||
      !(distinct_transform_rad > 0)) {
    throw UsageError(
        "landmarks: place recognition needs positive path lengths, ranges, tolerances and "
        "gates, and min_inliers >= 3");
  }
  if (!(max_correction_m > 0) || !(max_correction_per_m >= 0) || !(max_correction_rad > 0) ||
      !(max_correction_rad_per_m >= 0)) {
    throw UsageError("landmarks: the loop drift bound must be > 0 (its per-metre parts >= 0)");
  }
}

namespace {

// Old landmarks by 1 m cells, for the inlier count of a transform.
class CellIndex {
 public:
  CellIndex(const std::vector<Landmark>& landmarks, const std::vector<std::size_t>& members,
            double cell_m)
      : landmarks_(landmarks), cell_m_(cell_m) {
    for (std::size_t i : members) cells_[Key(landmarks[i].position_world)].push_back(i);
  }
  // The member nearest to p within gate_m with a radius within radius_gate_m, if any.
  std::optional<std::size_t> Nearest(const Eigen::Vector2d& p, double radius_m, double gate_m,
                                     double radius_gate_m) const {
    std::optional<std::size_t> best;
    double best_distance = gate_m;
    const long cx = Cell(p.x()), cy = Cell(p.y());
    for (long dx = -1; dx <= 1; ++dx) {
      for (long dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(Pack(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (std::size_t i : it->second) {
          const Landmark& l = landmarks_[i];
          const double d = (l.position_world - p).norm();
          if (d <= best_distance && std::abs(l.radius_m - radius_m) <= radius_gate_m) {
            best_distance = d;
            best = i;
          }
        }
      }
    }
    return best;
  }

 private:
  long Cell(double v) const { return static_cast<long>(std::floor(v / cell_m_)); }
  static long long Pack(long x, long y) {
    return (static_cast<long long>(x) << 32) ^ static_cast<long long>(static_cast<unsigned>(y));
  }
  long long Key(const Eigen::Vector2d& p) const { return Pack(Cell(p.x()), Cell(p.y())); }

  const std::vector<Landmark>& landmarks_;
  double cell_m_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

// Least-squares rigid transform taking points a onto points b (Umeyama 1991 without scale).
PlanarPose RigidTransform(const std::vector<Eigen::Vector2d>& a,
                          const std::vector<Eigen::Vector2d>& b) {
  Eigen::Vector2d mean_a = Eigen::Vector2d::Zero(), mean_b = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    mean_a += a[i];
    mean_b += b[i];
  }
  mean_a /= static_cast<double>(a.size());
  mean_b /= static_cast<double>(b.size());
  double sin_sum = 0, cos_sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d p = a[i] - mean_a, q = b[i] - mean_b;
    cos_sum += p.dot(q);
    sin_sum += p.x() * q.y() - p.y() * q.x();
  }
  const double theta = std::atan2(sin_sum, cos_sum);
  const double c = std::cos(theta), s = std::sin(theta);
  const Eigen::Vector2d t =
      mean_b - Eigen::Vector2d(c * mean_a.x() - s * mean_a.y(), s * mean_a.x() + c * mean_a.y());
  return {t.x(), t.y(), theta};
}

struct Hypothesis {
  PlanarPose T_old_local;
  std::vector<std::pair<std::size_t, std::size_t>> matches;
};

}  // namespace

LandmarkMap::LandmarkMap(const LandmarkMapOptions& options) : options_(options) {
  options_.Validate();
}

std::size_t LandmarkMap::AddKeyFrame(std::size_t key_frame, const PlanarPose& T_world_keyframe,
                                     double path_m,
                                     const std::vector<LandmarkObservation>& observations) {
  struct Candidate {
    double distance_m;
    std::size_t observation;
    std::size_t landmark;
  };
  std::vector<Eigen::Vector2d> world(observations.size());
  for (std::size_t i = 0; i < observations.size(); ++i) {
    world[i] = Transform(T_world_keyframe, observations[i].centre_base);
  }
  std::vector<Candidate> candidates;
  for (std::size_t l = 0; l < landmarks_.size(); ++l) {
    const Landmark& landmark = landmarks_[l];
    if (landmark.merged || landmark.last_seen_path_m < path_m - options_.active_path_m) continue;
    for (std::size_t i = 0; i < observations.size(); ++i) {
      const double d = (landmark.position_world - world[i]).norm();
      if (d <= options_.association_gate_m &&
          std::abs(landmark.radius_m - observations[i].radius_m) <= options_.radius_gate_m) {
        candidates.push_back({d, i, l});
      }
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance_m < b.distance_m; });
  std::vector<std::optional<std::size_t>> assigned(observations.size());
  std::vector<bool> taken(landmarks_.size(), false);
  std::size_t associated = 0;
  for (const Candidate& c : candidates) {
    if (assigned[c.observation] || taken[c.landmark]) continue;
    assigned[c.observation] = c.landmark;
    taken[c.landmark] = true;
    ++associated;
  }
  for (std::size_t i = 0; i < observations.size(); ++i) {
    if (!assigned[i]) {
      Landmark landmark;
      landmark.position_world = world[i];
      landmark.radius_m = observations[i].radius_m;
      landmark.first_seen_path_m = path_m;
      assigned[i] = landmarks_.size();
      landmarks_.push_back(landmark);
    }
    Landmark& landmark = landmarks_[*assigned[i]];
    const double n = static_cast<double>(landmark.observations);
    // Running means until the next optimisation recomputes them from the poses.
    landmark.position_world = (landmark.position_world * n + world[i]) / (n + 1);
    landmark.radius_m = (landmark.radius_m * n + observations[i].radius_m) / (n + 1);
    landmark.radius_sq_sum_m2 += observations[i].radius_m * observations[i].radius_m;
    ++landmark.observations;
    landmark.last_seen_path_m = path_m;
    landmark.last_key_frame = key_frame;
    sightings_.push_back({key_frame, *assigned[i], observations[i]});
  }
  return associated;
}

std::optional<LandmarkLoop> LandmarkMap::FindLoop(
    const PlanarPose& T_world_current, double path_m,
    const std::vector<double>& graph_distance_m) const {
  const Eigen::Vector2d here(T_world_current.x_m, T_world_current.y_m);
  const auto bound_m = [&](double graph_m) {
    return options_.max_correction_m + options_.max_correction_per_m * graph_m;
  };
  const auto graph_m = [&](const Landmark& l) {
    return l.last_key_frame < graph_distance_m.size() &&
                   std::isfinite(graph_distance_m[l.last_key_frame])
               ? graph_distance_m[l.last_key_frame]
               : path_m - l.last_seen_path_m;
  };
  std::vector<std::size_t> local, old;
  for (std::size_t i = 0; i < landmarks_.size(); ++i) {
    const Landmark& l = landmarks_[i];
    if (l.merged || l.observations < options_.min_graph_observations) continue;
    if (l.last_seen_path_m >= path_m - options_.local_path_m) {
      local.push_back(i);
    } else if (l.last_seen_path_m < path_m - options_.min_loop_path_m &&
               (l.position_world - here).norm() <=
                   options_.max_search_range_m + bound_m(graph_m(l))) {
      old.push_back(i);
    }
  }
  if (local.size() < options_.min_inliers || old.size() < options_.min_inliers) {
    return std::nullopt;
  }
  struct Pair {
    double distance_m;
    std::size_t a, b;
  };
  std::vector<Pair> old_pairs;
  for (std::size_t i = 0; i < old.size(); ++i) {
    for (std::size_t j = i + 1; j < old.size(); ++j) {
      const double d =
          (landmarks_[old[i]].position_world - landmarks_[old[j]].position_world).norm();
      if (d >= options_.min_pair_distance_m) old_pairs.push_back({d, old[i], old[j]});
    }
  }
  std::sort(old_pairs.begin(), old_pairs.end(),
            [](const Pair& x, const Pair& y) { return x.distance_m < y.distance_m; });
  const CellIndex index(landmarks_, old, std::max(options_.inlier_gate_m, 1.0));

  const auto score = [&](const PlanarPose& T) {
    Hypothesis h{T, {}};
    std::vector<std::size_t> used;
    for (std::size_t i : local) {
      const Landmark& l = landmarks_[i];
      const auto match = index.Nearest(Transform(T, l.position_world), l.radius_m,
                                       options_.inlier_gate_m, options_.radius_gate_m);
      if (!match || std::find(used.begin(), used.end(), *match) != used.end()) continue;
      used.push_back(*match);
      h.matches.emplace_back(i, *match);
    }
    return h;
  };
  std::vector<Hypothesis> hypotheses;
  for (std::size_t x = 0; x < local.size(); ++x) {
    for (std::size_t y = x + 1; y < local.size(); ++y) {
      const Landmark& li = landmarks_[local[x]];
      const Landmark& lj = landmarks_[local[y]];
      const Eigen::Vector2d dij = lj.position_world - li.position_world;
      const double d = dij.norm();
      if (d < options_.min_pair_distance_m) continue;
      auto it = std::lower_bound(old_pairs.begin(), old_pairs.end(), d - options_.pair_tolerance_m,
                                 [](const Pair& p, double value) { return p.distance_m < value; });
      for (; it != old_pairs.end() && it->distance_m <= d + options_.pair_tolerance_m; ++it) {
        for (int flip = 0; flip < 2; ++flip) {
          const Landmark& la = landmarks_[flip == 0 ? it->a : it->b];
          const Landmark& lb = landmarks_[flip == 0 ? it->b : it->a];
          if (std::abs(la.radius_m - li.radius_m) > options_.radius_gate_m ||
              std::abs(lb.radius_m - lj.radius_m) > options_.radius_gate_m) {
            continue;
          }
          const Eigen::Vector2d dab = lb.position_world - la.position_world;
          const double theta =
              WrapAngle(std::atan2(dab.y(), dab.x()) - std::atan2(dij.y(), dij.x()));
          const double c = std::cos(theta), s = std::sin(theta);
          const Eigen::Vector2d t =
              la.position_world -
              Eigen::Vector2d(c * li.position_world.x() - s * li.position_world.y(),
                              s * li.position_world.x() + c * li.position_world.y());
          const PlanarPose T{t.x(), t.y(), theta};
          // The drift bound, checked on the robot's own position before scoring.
          const PlanarPose corrected = Compose(T, T_world_current);
          const double graph = std::min(graph_m(la), graph_m(lb));
          if (std::hypot(corrected.x_m - here.x(), corrected.y_m - here.y()) > bound_m(graph) ||
              std::abs(theta) >
                  options_.max_correction_rad + options_.max_correction_rad_per_m * graph) {
            continue;
          }
          Hypothesis h = score(T);
          if (h.matches.size() >= 3) hypotheses.push_back(std::move(h));
        }
      }
    }
  }
  if (hypotheses.empty()) return std::nullopt;
  const auto best_it = std::max_element(
      hypotheses.begin(), hypotheses.end(),
      [](const Hypothesis& a, const Hypothesis& b) { return a.matches.size() < b.matches.size(); });
  // Refine on the inliers, then count again.
  std::vector<Eigen::Vector2d> from, to;
  for (const auto& [l, o] : best_it->matches) {
    from.push_back(landmarks_[l].position_world);
    to.push_back(landmarks_[o].position_world);
  }
  Hypothesis best = score(RigidTransform(from, to));
  if (best.matches.size() < best_it->matches.size()) best = *best_it;
  if (best.matches.size() < options_.min_inliers) return std::nullopt;
  from.clear();
  to.clear();
  for (const auto& [l, o] : best.matches) {
    from.push_back(landmarks_[l].position_world);
    to.push_back(landmarks_[o].position_world);
  }
  best.T_old_local = RigidTransform(from, to);
  // Spread in two dimensions.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : to) mean += p;
  mean /= static_cast<double>(to.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& p : to) scatter += (p - mean) * (p - mean).transpose();
  scatter /= static_cast<double>(to.size());
  const double thinnest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvalues()(0);
  if (std::sqrt(std::max(thinnest, 0.0)) < options_.min_inlier_spread_m) return std::nullopt;
  // Clearly better than any transform that differs.
  std::size_t runner_up = 0;
  for (const Hypothesis& h : hypotheses) {
    const PlanarPose apart = Between(h.T_old_local, best.T_old_local);
    if (std::hypot(apart.x_m, apart.y_m) > options_.distinct_transform_m ||
        std::abs(apart.theta_rad) > options_.distinct_transform_rad) {
      runner_up = std::max(runner_up, h.matches.size());
    }
  }
  if (best.matches.size() < runner_up + options_.min_inlier_margin) return std::nullopt;
  LandmarkLoop loop;
  loop.matches = std::move(best.matches);
  loop.T_old_local = best.T_old_local;
  loop.runner_up_inliers = runner_up;
  return loop;
}

void LandmarkMap::Merge(const LandmarkLoop& loop) {
  std::unordered_map<std::size_t, std::size_t> relabel;
  for (const auto& [local, old] : loop.matches) {
    if (local == old) continue;
    relabel[local] = old;
    Landmark& target = landmarks_.at(old);
    Landmark& source = landmarks_.at(local);
    target.radius_m = (target.radius_m * static_cast<double>(target.observations) +
                       source.radius_m * static_cast<double>(source.observations)) /
                      static_cast<double>(target.observations + source.observations);
    target.radius_sq_sum_m2 += source.radius_sq_sum_m2;
    target.observations += source.observations;
    if (source.last_seen_path_m >= target.last_seen_path_m) {
      target.last_seen_path_m = source.last_seen_path_m;
      target.last_key_frame = source.last_key_frame;
    }
    target.first_seen_path_m = std::min(target.first_seen_path_m, source.first_seen_path_m);
    source.merged = true;
    source.observations = 0;
    source.radius_sq_sum_m2 = 0;
  }
  for (LandmarkSighting& s : sightings_) {
    if (const auto it = relabel.find(s.landmark); it != relabel.end()) s.landmark = it->second;
  }
}

void LandmarkMap::UpdatePositions(const std::vector<PlanarPose>& key_frame_poses) {
  std::vector<Eigen::Vector2d> sum(landmarks_.size(), Eigen::Vector2d::Zero());
  std::vector<double> radius(landmarks_.size(), 0);
  std::vector<std::size_t> count(landmarks_.size(), 0);
  for (const LandmarkSighting& s : sightings_) {
    if (s.key_frame >= key_frame_poses.size()) continue;
    sum[s.landmark] += Transform(key_frame_poses[s.key_frame], s.observation.centre_base);
    radius[s.landmark] += s.observation.radius_m;
    ++count[s.landmark];
  }
  for (std::size_t i = 0; i < landmarks_.size(); ++i) {
    if (count[i] == 0) continue;
    landmarks_[i].position_world = sum[i] / static_cast<double>(count[i]);
    landmarks_[i].radius_m = radius[i] / static_cast<double>(count[i]);
  }
}

bool LandmarkMap::InGraph(const Landmark& landmark) const {
  if (landmark.merged || landmark.observations < options_.min_graph_observations) return false;
  const double n = static_cast<double>(landmark.observations);
  const double variance_m2 = landmark.radius_sq_sum_m2 / n - landmark.radius_m * landmark.radius_m;
  return variance_m2 <= options_.max_graph_radius_spread_m * options_.max_graph_radius_spread_m;
}

std::size_t LandmarkMap::graph_landmarks() const {
  return static_cast<std::size_t>(std::count_if(landmarks_.begin(), landmarks_.end(),
                                                [&](const Landmark& l) { return InGraph(l); }));
}

}  // namespace littermap::reconstruct
