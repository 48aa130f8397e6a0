#include "sim/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "sim/random.hpp"

namespace littermap::sim {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr int kWaveCount = 3;
constexpr double kRootSigmaM = 0.12;

bool InsidePatch(const GroundPatch& patch, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - patch.center_m;
  const double r = d.norm();
  if (r > 1.2 * patch.radius_m) return false;
  const double phi = std::atan2(d.y(), d.x());
  return r <= patch.radius_m * (1 + 0.2 * std::sin(3 * phi + patch.phase_rad));
}

}  // namespace

const char* GroundTypeName(GroundType type) {
  switch (type) {
    case GroundType::kGrass:
      return "grass";
    case GroundType::kDirtPath:
      return "dirt_path";
    case GroundType::kLeafLitter:
      return "leaf_litter";
    case GroundType::kGravel:
      return "gravel";
  }
  return "grass";
}

double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

Terrain::Terrain(const WorldSpec& spec, std::uint64_t seed) : paths_(spec.terrain.paths) {
  Rng rng(seed, 101);
  const TerrainSpec& t = spec.terrain;
  // Hills: wavelengths 1x, 1.7x, 2.9x the shortest, amplitudes sharing hill_amplitude_m.
  for (int i = 0; i < kWaveCount; ++i) {
    const double angle = rng.Uniform(0, kTwoPi);
    HeightWave wave{{std::cos(angle), std::sin(angle)},
                    t.hill_amplitude_m / kWaveCount,
                    t.hill_wavelength_m * std::pow(1.7, i),
                    rng.Uniform(0, kTwoPi)};
    max_slope_ += wave.amplitude_m * kTwoPi / wave.wavelength_m;
    waves_.push_back(wave);
  }
  for (int i = 0; i < t.roots; ++i) {
    roots_.push_back({{rng.Uniform(0, spec.size_x_m), rng.Uniform(0, spec.size_y_m)},
                      t.root_height_m * rng.Uniform(0.5, 1.0),
                      kRootSigmaM});
  }
  cells_x_ = static_cast<int>(std::ceil(spec.size_x_m)) + 2;
  cells_y_ = static_cast<int>(std::ceil(spec.size_y_m)) + 2;
  root_cells_.resize(static_cast<std::size_t>(cells_x_ * cells_y_));
  for (std::size_t i = 0; i < roots_.size(); ++i) {
    const Eigen::Vector2d c = roots_[i].center_m;
    const double reach = 4 * kRootSigmaM;
    for (int x = int(std::floor(c.x() - reach)); x <= int(std::floor(c.x() + reach)); ++x) {
      for (int y = int(std::floor(c.y() - reach)); y <= int(std::floor(c.y() + reach)); ++y) {
        if (x + 1 < 0 || y + 1 < 0 || x + 1 >= cells_x_ || y + 1 >= cells_y_) continue;
        root_cells_[static_cast<std::size_t>((y + 1) * cells_x_ + x + 1)].push_back(int(i));
      }
    }
  }
  max_hill_slope_ = max_slope_;
  max_root_height_m_ = 2 * t.root_height_m;  // two overlapping roots
  // max |d/dr h exp(-r²/2σ²)| = h/σ e^{-1/2}; doubled for two overlapping roots.
  max_slope_ += 2 * t.root_height_m / kRootSigmaM * std::exp(-0.5);
  const auto add_patches = [&](int count, GroundType type) {
    for (int i = 0; i < count; ++i) {
      patches_.push_back({type,
                          {rng.Uniform(0, spec.size_x_m), rng.Uniform(0, spec.size_y_m)},
                          t.patch_radius_m * rng.Uniform(0.6, 1.4),
                          rng.Uniform(0, kTwoPi)});
    }
  };
  add_patches(t.leaf_patches, GroundType::kLeafLitter);
  add_patches(t.gravel_patches, GroundType::kGravel);
}

const std::vector<int>& Terrain::RootsNear(const Eigen::Vector2d& p) const {
  static const std::vector<int> kNone;
  // Cell (x, y) covers [x - 1, x) x [y - 1, y): one cell of margin around the park.
  const double fx = std::floor(p.x()) + 1, fy = std::floor(p.y()) + 1;
  if (!(fx >= 0 && fy >= 0 && fx < cells_x_ && fy < cells_y_)) return kNone;
  return root_cells_[static_cast<std::size_t>(static_cast<int>(fy) * cells_x_ +
                                              static_cast<int>(fx))];
}

double Terrain::HillHeightAt(const Eigen::Vector2d& p) const {
  double h = 0;
  for (const HeightWave& w : waves_) {
    h += w.amplitude_m * std::sin(w.direction.dot(p) * kTwoPi / w.wavelength_m + w.phase_rad);
  }
  return h;
}

double Terrain::RootHeightAt(const Eigen::Vector2d& p) const {
  double h = 0;
  for (const int i : RootsNear(p)) {
    const Root& root = roots_[static_cast<std::size_t>(i)];
    const double r2 = (p - root.center_m).squaredNorm();
    if (r2 < 16 * root.sigma_m * root.sigma_m) {
      h += root.height_m * std::exp(-r2 / (2 * root.sigma_m * root.sigma_m));
    }
  }
  return h;
}

double Terrain::HeightAt(const Eigen::Vector2d& p) const {
  return HillHeightAt(p) + RootHeightAt(p);
}

Eigen::Vector2d Terrain::GradientAt(const Eigen::Vector2d& p) const {
  Eigen::Vector2d g = Eigen::Vector2d::Zero();
  for (const HeightWave& w : waves_) {
    const double k = kTwoPi / w.wavelength_m;
    g += w.amplitude_m * k * std::cos(w.direction.dot(p) * k + w.phase_rad) * w.direction;
  }
  for (const int i : RootsNear(p)) {
    const Root& root = roots_[static_cast<std::size_t>(i)];
    const Eigen::Vector2d d = p - root.center_m;
    const double s2 = root.sigma_m * root.sigma_m;
    if (d.squaredNorm() < 16 * s2) {
      g += -root.height_m * std::exp(-d.squaredNorm() / (2 * s2)) / s2 * d;
    }
  }
  return g;
}

double Terrain::DistanceToPathEdge(const Eigen::Vector2d& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const PathSpec& path : paths_) {
    for (std::size_t i = 0; i + 1 < path.points_m.size(); ++i) {
      best = std::min(
          best, DistanceToSegment(p, path.points_m[i], path.points_m[i + 1]) - 0.5 * path.width_m);
    }
  }
  return best;
}

GroundType Terrain::GroundAt(const Eigen::Vector2d& p) const {
  if (DistanceToPathEdge(p) < 0) return GroundType::kDirtPath;
  // Later patches win: gravel (added last) lies on top of leaf litter.
  for (auto it = patches_.rbegin(); it != patches_.rend(); ++it) {
    if (InsidePatch(*it, p)) return it->type;
  }
  return GroundType::kGrass;
}

}  // namespace littermap::sim
