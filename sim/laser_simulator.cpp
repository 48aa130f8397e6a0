#include "sim/laser_simulator.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "sim/random.hpp"

namespace littermap::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDegToRad = std::numbers::pi / 180;

// Smallest t > 0 with t·t·a + 2·t·b + c = 0, or +inf.
double SmallestRoot(double a, double b, double c) {
  const double discriminant = b * b - a * c;
  if (a <= 0 || discriminant < 0) return kInf;
  const double s = std::sqrt(discriminant);
  const double t1 = (-b - s) / a, t2 = (-b + s) / a;
  return t1 > 0 ? t1 : (t2 > 0 ? t2 : kInf);
}

// Ray against the axis-aligned box |p| <= h (slab method).
double HitBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& h) {
  double t_near = -kInf, t_far = kInf;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-12) {
      if (std::abs(o[i]) > h[i]) return kInf;
      continue;
    }
    double t1 = (-h[i] - o[i]) / d[i], t2 = (h[i] - o[i]) / d[i];
    if (t1 > t2) std::swap(t1, t2);
    t_near = std::max(t_near, t1);
    t_far = std::min(t_far, t2);
  }
  if (t_near > t_far || t_far <= 0) return kInf;
  return t_near > 0 ? t_near : t_far;
}

// Ray against the cylinder x² + y² <= r², |z| <= h along z.
double HitCylinder(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double r, double h) {
  double best = kInf;
  const double t_side = SmallestRoot(d.x() * d.x() + d.y() * d.y(), o.x() * d.x() + o.y() * d.y(),
                                     o.x() * o.x() + o.y() * o.y() - r * r);
  if (t_side < kInf && std::abs(o.z() + t_side * d.z()) <= h) best = t_side;
  if (std::abs(d.z()) > 1e-12) {
    for (const double cap : {-h, h}) {
      const double t = (cap - o.z()) / d.z();
      const Eigen::Vector3d p = o + t * d;
      if (t > 0 && t < best && p.x() * p.x() + p.y() * p.y() <= r * r) best = t;
    }
  }
  return best;
}

// Ray against the ellipsoid with semi-axes h: scaled to the unit sphere, t is unchanged.
double HitEllipsoid(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& h) {
  const Eigen::Vector3d os = o.cwiseQuotient(h), ds = d.cwiseQuotient(h);
  return SmallestRoot(ds.squaredNorm(), os.dot(ds), os.squaredNorm() - 1);
}

}  // namespace

LaserModel LaserPreset(const std::string& name) {
  if (name == "urg-04lx") return {name, 240 * kDegToRad, 682, 0.02, 5.6};
  if (name == "utm-30lx") return {name, 270 * kDegToRad, 1081, 0.1, 30.0};
  throw UsageError("unknown laser preset '" + name + "' (urg-04lx or utm-30lx)");
}

LaserSimulator::LaserSimulator(const World& world, LaserSimulatorOptions options)
    : world_(world), options_(std::move(options)) {
  for (const WorldObject& o : world.objects) {
    const Eigen::Matrix3d R_world_object = RotationFromRpy(o.orientation);
    primitives_.push_back(
        {o.shape, R_world_object.transpose(), o.center_m, 0.5 * o.size_m, 0.5 * o.size_m.norm()});
  }
  for (const HeightWave& wave : world.terrain.waves()) max_terrain_height_m_ += wave.amplitude_m;
  for (const Root& root : world.terrain.roots()) {
    max_terrain_height_m_ = std::max(max_terrain_height_m_, root.height_m);
  }
  max_terrain_height_m_ += world.spec.terrain.root_height_m * 2;  // overlapping roots
}

double LaserSimulator::CastTerrain(const Eigen::Vector3d& origin, const Eigen::Vector3d& d,
                                   double max_range_m) const {
  // Conservative marching (sphere tracing on a height field): the gap g = z - h(x, y) shrinks at
  // most at rate G·|d_xy| - d_z per metre of ray, G the terrain's slope bound, so g / rate is a
  // safe step. Two bounds, the larger step wins: the whole terrain (steep roots in G), and the
  // smooth hills alone with the roots' height taken off the gap. Near grazing hits, a minimum
  // step of 1 cm + 1 % of the distance (at most a few mm of root missed) then bisection on the
  // sign change keep the number of steps small.
  const Terrain& terrain = world_.terrain;
  const double run = d.head<2>().norm();
  const double closing = terrain.max_slope() * run - d.z();
  const double closing_hills = terrain.max_hill_slope() * run - d.z();
  if (closing <= 0 && origin.z() > max_terrain_height_m_) return kInf;
  const auto gap_at = [&](double t, double* hill_gap) {
    const Eigen::Vector3d p = origin + t * d;
    const double hills = terrain.HillHeightAt(p.head<2>());
    *hill_gap = p.z() - hills - terrain.max_root_height_m();
    return p.z() - hills - terrain.RootHeightAt(p.head<2>());
  };
  double hill_gap = 0, t = 0, gap = gap_at(0, &hill_gap);
  if (gap <= 0) return 0;  // the laser is in the ground
  for (int i = 0; i < 1000 && t <= max_range_m; ++i) {
    if (closing_hills <= 0 && hill_gap > 0) return kInf;  // climbing away from everything
    double step = std::max(closing > 0 ? gap / closing : kInf, 0.01 + 0.01 * t);
    if (closing_hills > 0 && hill_gap > 0) step = std::max(step, hill_gap / closing_hills);
    const double t_next = t + std::min(step, max_range_m + 0.01 - t);
    double hill_gap_next = 0;
    const double gap_next = gap_at(t_next, &hill_gap_next);
    if (gap_next < 1e-7) {
      double lo = t, hi = t_next, ignored = 0;  // gap(lo) > 0 >= gap(hi)
      for (int k = 0; k < 40 && hi - lo > 1e-6; ++k) {
        const double mid = 0.5 * (lo + hi);
        (gap_at(mid, &ignored) > 0 ? lo : hi) = mid;
      }
      return hi;
    }
    if (t_next > max_range_m) return kInf;
    t = t_next;
    gap = gap_next;
    hill_gap = hill_gap_next;
  }
  return kInf;
}

double LaserSimulator::CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                               double max_range_m,
                               const std::vector<const Primitive*>& candidates) const {
  double best = CastTerrain(origin, direction, max_range_m);
  for (const Primitive* p : candidates) {
    // Skip primitives whose bounding sphere the ray misses or that lie beyond the best hit.
    const Eigen::Vector3d to_center = p->center_m - origin;
    const double along = to_center.dot(direction);
    const double r = p->bounding_radius_m;
    if (along + r < 0 || along - r > best) continue;
    if ((to_center - along * direction).squaredNorm() > r * r) continue;
    const Eigen::Vector3d o = p->R_object_world * (origin - p->center_m);
    const Eigen::Vector3d d = p->R_object_world * direction;
    double t = kInf;
    switch (p->shape) {
      case Shape::kBox:
        t = HitBox(o, d, p->half_size_m);
        break;
      case Shape::kCylinder:
        t = HitCylinder(o, d, p->half_size_m.x(), p->half_size_m.z());
        break;
      case Shape::kEllipsoid:
        t = HitEllipsoid(o, d, p->half_size_m);
        break;
    }
    best = std::min(best, t);
  }
  return best <= max_range_m ? best : kInf;
}

double LaserSimulator::CastRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                               double max_range_m) const {
  std::vector<const Primitive*> all;
  for (const Primitive& p : primitives_) all.push_back(&p);
  return CastRay(origin, direction, max_range_m, all);
}

std::vector<std::vector<const LaserSimulator::Primitive*>> LaserSimulator::CandidatesPerBeam(
    const Eigen::Isometry3d& T_world_laser, const LaserScan& scan) const {
  // Every beam lies in the laser's x-y plane: a primitive can only be hit by the beams whose
  // angles cross its bounding sphere's shadow there, and not at all if the sphere misses the
  // plane (most litter, crowns). This culls nearly all ray-primitive tests.
  const std::size_t beams = static_cast<std::size_t>(options_.model.beams);
  std::vector<std::vector<const Primitive*>> candidates(beams);
  const Eigen::Isometry3d T_laser_world = T_world_laser.inverse();
  const double inc = scan.angle_increment_rad;
  for (const Primitive& p : primitives_) {
    const Eigen::Vector3d c = T_laser_world * p.center_m;
    const double r = p.bounding_radius_m, rho = std::hypot(c.x(), c.y());
    if (std::abs(c.z()) > r || rho - r > options_.model.range_max_m) continue;
    if (rho <= r) {  // the laser is inside the bounding sphere: every beam may hit
      for (auto& list : candidates) list.push_back(&p);
      continue;
    }
    const double half = std::asin(r / rho);
    const double center = std::atan2(c.y(), c.x());
    for (const double shift : {-2 * std::numbers::pi, 0.0, 2 * std::numbers::pi}) {
      const double lo = (center - half + shift - scan.angle_min_rad) / inc;
      const double hi = (center + half + shift - scan.angle_min_rad) / inc;
      if (hi < -1 || lo > static_cast<double>(beams)) continue;
      const auto first = static_cast<std::size_t>(std::max(0.0, std::floor(lo)));
      const auto last = std::min(beams - 1, static_cast<std::size_t>(std::max(0.0, std::ceil(hi))));
      for (std::size_t i = first; i <= last; ++i) candidates[i].push_back(&p);
    }
  }
  return candidates;
}

LaserScan LaserSimulator::Scan(const Eigen::Isometry3d& T_world_laser, TimestampNs stamp_ns,
                               std::uint64_t seed, std::uint64_t scan_index) const {
  const LaserModel& model = options_.model;
  LaserScan scan;
  scan.stamp_ns = stamp_ns;
  scan.angle_min_rad = -0.5 * model.fov_rad;
  scan.angle_increment_rad = model.fov_rad / (model.beams - 1);
  scan.range_min_m = model.range_min_m;
  scan.range_max_m = model.range_max_m;
  const Eigen::Vector3d origin = T_world_laser.translation();
  const auto candidates = CandidatesPerBeam(T_world_laser, scan);
  std::vector<double> truth(static_cast<std::size_t>(model.beams));
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double a = scan.AngleOf(i);
    const Eigen::Vector3d d = T_world_laser.linear() * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
    truth[i] = CastRay(origin, d, model.range_max_m, candidates[i]);
  }
  Rng rng(seed, 1'000'000 + scan_index);
  scan.ranges_m.resize(truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    // Fixed draws per beam keep the stream aligned whatever the geometry.
    const double noise = rng.Normal(), u_mix = rng.Uniform01(), u_where = rng.Uniform01();
    const double u_drop = rng.Uniform01();
    double r = truth[i];
    if (i + 1 < truth.size() && std::isfinite(r) && std::isfinite(truth[i + 1]) &&
        std::abs(r - truth[i + 1]) > options_.edge_jump_m &&
        u_mix < options_.mixed_pixel_probability) {
      r += u_where * (truth[i + 1] - r);  // the spot straddles both surfaces
    }
    if (std::isfinite(r)) r += options_.range_noise_sigma_m * noise;
    if (u_drop < options_.dropout_probability || r > model.range_max_m) r = kInf;
    scan.ranges_m[i] = static_cast<float>(r);
  }
  return scan;
}

}  // namespace littermap::sim
