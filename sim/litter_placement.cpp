// Litter and natural look-alikes. Litter follows a clustered (Thomas-like) process: a share
// hotspot_fraction of the items scatter with a Gaussian around hotspots (benches and bins weigh
// 3, points along path edges 1), the rest fall uniformly, as litter surveys report accumulation
// at rest places and path edges. Sizes and colours are those of real items (TACO classes).

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "sim/footprint.hpp"
#include "sim/litter_wear.hpp"
#include "sim/random.hpp"
#include "sim/world.hpp"

namespace littermap::sim {
namespace {

constexpr double kPi = std::numbers::pi;

struct Kind {
  Shape shape;
  Eigen::Vector3d size_m;
  double lying_probability;  // a cylinder or cone on its side
  std::vector<Eigen::Vector3d> colours;
  const char* texture;
  double raised_m = 0;  // flowers sit on a stem
};

const std::map<std::string, Kind>& Catalog() {
  static const std::map<std::string, Kind> kinds = {
      {"can",
       {Shape::kCylinder,
        {0.066, 0.066, 0.12},
        0.7,
        {{0.8, 0.1, 0.1}, {0.75, 0.75, 0.78}, {0.1, 0.2, 0.7}, {0.1, 0.5, 0.2}},
        "aluminium"}},
      {"bottle",
       {Shape::kCylinder,
        {0.07, 0.07, 0.25},
        0.9,
        {{0.8, 0.85, 0.9}, {0.2, 0.5, 0.3}, {0.4, 0.25, 0.1}},
        "plastic"}},
      {"cup",
       {Shape::kCylinder,
        {0.08, 0.08, 0.1},
        0.6,
        {{0.95, 0.95, 0.95}, {0.55, 0.4, 0.25}},
        "paper"}},
      {"carton",
       {Shape::kBox,
        {0.2, 0.1, 0.07},
        0,
        {{0.9, 0.9, 0.85}, {0.95, 0.8, 0.1}, {0.2, 0.4, 0.8}},
        "cardboard"}},
      {"food_container", {Shape::kBox, {0.2, 0.15, 0.06}, 0, {{0.97, 0.97, 0.95}}, "styrofoam"}},
      {"plastic_bag",
       {Shape::kBox,
        {0.3, 0.25, 0.02},
        0,
        {{0.95, 0.95, 0.95}, {0.2, 0.3, 0.8}, {0.05, 0.05, 0.05}},
        "plastic_film"}},
      {"other",
       {Shape::kBox, {0.09, 0.055, 0.02}, 0, {{0.85, 0.15, 0.15}, {0.8, 0.65, 0.2}}, "paper"}},
      {"flower_red",
       {Shape::kEllipsoid, {0.05, 0.05, 0.03}, 0, {{0.85, 0.1, 0.1}}, "petals", 0.15}},
      {"flower_yellow",
       {Shape::kEllipsoid, {0.04, 0.04, 0.03}, 0, {{0.95, 0.85, 0.1}}, "petals", 0.12}},
      {"flower_white",
       {Shape::kEllipsoid, {0.035, 0.035, 0.02}, 0, {{0.95, 0.95, 0.9}}, "petals", 0.1}},
      {"flower_purple",
       {Shape::kEllipsoid, {0.04, 0.04, 0.04}, 0, {{0.5, 0.2, 0.65}}, "petals", 0.15}},
      {"leaf",
       {Shape::kBox,
        {0.08, 0.06, 0.004},
        0,
        {{0.85, 0.45, 0.1}, {0.7, 0.15, 0.05}, {0.5, 0.3, 0.1}, {0.9, 0.75, 0.2}},
        "leaf"}},
      {"stone",
       {Shape::kEllipsoid,
        {0.08, 0.06, 0.05},
        0,
        {{0.55, 0.55, 0.52}, {0.7, 0.68, 0.62}},
        "stone"}},
      {"pine_cone", {Shape::kEllipsoid, {0.045, 0.045, 0.08}, 0.9, {{0.4, 0.25, 0.12}}, "cone"}},
      {"branch", {Shape::kCylinder, {0.03, 0.03, 0.6}, 1.0, {{0.35, 0.25, 0.15}}, "bark"}},
      {"mushroom",
       {Shape::kCylinder,
        {0.06, 0.06, 0.06},
        0,
        {{0.95, 0.92, 0.85}, {0.8, 0.1, 0.05}},
        "mushroom"}},
  };
  return kinds;
}

// Exact counts per class from weights (largest remainder), in the map's key order.
std::vector<std::string> AllocateLabels(const std::map<std::string, double>& weights, int total) {
  double sum = 0;
  for (const auto& [label, weight] : weights) sum += weight;
  std::vector<std::string> labels;
  if (sum <= 0 || total <= 0) return labels;
  std::vector<std::pair<double, std::string>> remainders;
  for (const auto& [label, weight] : weights) {
    const double share = total * weight / sum;
    labels.insert(labels.end(), static_cast<std::size_t>(std::floor(share)), label);
    remainders.emplace_back(share - std::floor(share), label);
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t i = 0; labels.size() < static_cast<std::size_t>(total); ++i) {
    labels.push_back(remainders[i].second);
  }
  return labels;
}

bool InsideStructure(const World& world, const Eigen::Vector2d& p) {
  for (const WorldObject& o : world.objects) {
    if (o.kind == ObjectKind::kLitter || o.kind == ObjectKind::kNatural ||
        o.label == "tree_crown") {
      continue;
    }
    const double radius = 0.5 * std::max(o.size_m.x(), o.size_m.y()) + 0.05;
    if ((p - o.center_m.head<2>()).norm() < radius) return true;
  }
  return false;
}

bool InPark(const World& world, const Eigen::Vector2d& p) {
  return p.x() > 0.2 && p.y() > 0.2 && p.x() < world.spec.size_x_m - 0.2 &&
         p.y() < world.spec.size_y_m - 0.2;
}

// How items on grass sink into it: with `probability`, by a share of their height drawn from
// [depth_min, depth_max].
struct Sinking {
  double probability = 0.3;
  double depth_min = 0.3, depth_max = 0.6;
};

// Clearance between two small objects: they may lie side by side, not through each other.
constexpr double kSmallObjectGapM = 0.02;

bool OverlapsSmallObject(const World& world, const Footprint& footprint) {
  for (const WorldObject& o : world.objects) {
    if ((o.kind == ObjectKind::kLitter || o.kind == ObjectKind::kNatural) &&
        FootprintsOverlap(footprint, FootprintOf(o), kSmallObjectGapM)) {
      return true;
    }
  }
  return false;
}

// Where `object` (posed, its centre at the proposed spot) is clear of every small object
// placed before it: the spot itself, or the first clear one of steps of 5 cm, 10 cm, ... away
// from it, each in a direction drawn from `rng`. Only an object that overlaps draws from `rng`, so
// a world where nothing overlaps draws what it drew before, and moving one object leaves every
// other where it was.
Eigen::Vector2d ClearOfSmallObjects(const World& world, const WorldObject& object, Rng& rng) {
  Footprint footprint = FootprintOf(object);
  const Eigen::Vector2d proposed = footprint.center_m;
  for (int step = 1; step <= 100 && OverlapsSmallObject(world, footprint); ++step) {
    const double angle = rng.Uniform(-kPi, kPi);
    const Eigen::Vector2d candidate =
        proposed + 0.05 * step * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    if (InPark(world, candidate) && !InsideStructure(world, candidate)) {
      footprint.center_m = candidate;
    }
  }
  return footprint.center_m;
}

// Places one small object of `label` near what `draw` proposes, worn as `wear` says (none for
// natural objects). A `spot` moves it there, unsunk, once every draw of `rng` is taken as
// without it, so that moving some items leaves the others where they were. An object that
// would share space with one placed before is moved clear with draws from `clear_rng`.
template <typename Draw>
void PlaceSmall(World& world, Rng& rng, Rng& clear_rng, ObjectKind kind, const std::string& label,
                const Sinking& sinking, const LitterWear* wear,
                const std::optional<Eigen::Vector2d>& spot, Draw draw) {
  const Kind& k = Catalog().at(label);
  Eigen::Vector2d p = draw();
  for (int i = 0; i < 100 && (!InPark(world, p) || InsideStructure(world, p)); ++i) p = draw();
  WorldObject o;
  o.kind = kind;
  o.label = label;
  o.shape = k.shape;
  o.size_m = k.size_m;
  if (label == "branch") o.size_m.z() = rng.Uniform(0.3, 1.0);
  if (label == "stone") o.size_m *= rng.Uniform(0.6, 1.6);
  o.colour_rgb = k.colours[static_cast<std::size_t>(rng.Index(int(k.colours.size())))];
  o.texture = k.texture;
  o.orientation.yaw_rad = rng.Uniform(-kPi, kPi);
  const bool lying = rng.Bernoulli(k.lying_probability);
  if (lying) o.orientation.pitch_rad = kPi / 2;  // the local z axis lies flat
  if (wear != nullptr) ApplyLitterWear(*wear, o);
  const double height = lying ? o.size_m.x() : o.size_m.z();
  const auto on_grass = [&world](const Eigen::Vector2d& at) {
    return world.terrain.GroundAt(at) == GroundType::kGrass;
  };
  const auto sunk = [&sinking](Rng& draws) {
    return draws.Bernoulli(sinking.probability)
               ? draws.Uniform(sinking.depth_min, sinking.depth_max)
               : 0.0;
  };
  if (on_grass(p)) o.hidden_fraction = sunk(rng);
  if (spot) {
    p = *spot;
    o.hidden_fraction = 0;
  }
  o.center_m.head<2>() = p;
  const Eigen::Vector2d clear = ClearOfSmallObjects(world, o, clear_rng);
  if (clear != p && !spot) {  // moved: the ground where it lies now decides how it sinks
    if (!on_grass(clear)) {
      o.hidden_fraction = 0;
    } else if (!on_grass(p)) {
      o.hidden_fraction = sunk(clear_rng);
    }
  }
  p = clear;
  o.center_m = {p.x(), p.y(),
                world.terrain.HeightAt(p) + k.raised_m + height * (0.5 - o.hidden_fraction)};
  AddObject(world, o);
}

std::vector<Eigen::Vector2d> PathEdgePoints(const Terrain& terrain) {
  std::vector<Eigen::Vector2d> points;
  for (const PathSpec& path : terrain.paths()) {
    for (std::size_t i = 0; i + 1 < path.points_m.size(); ++i) {
      const Eigen::Vector2d a = path.points_m[i], b = path.points_m[i + 1];
      const Eigen::Vector2d along = (b - a).normalized();
      const Eigen::Vector2d normal(-along.y(), along.x());
      for (double s = 2.5; s < (b - a).norm(); s += 5) {
        points.push_back(a + s * along + normal * 0.5 * path.width_m);
        points.push_back(a + s * along - normal * 0.5 * path.width_m);
      }
    }
  }
  return points;
}

// A point well inside a random gravel patch (on gravel, not on a path crossing it, clear of
// structure), or none when the park has no gravel.
std::optional<Eigen::Vector2d> OnGravel(const World& world, Rng& rng) {
  const Terrain& terrain = world.terrain;
  std::vector<const GroundPatch*> gravel;
  for (const GroundPatch& patch : terrain.patches()) {
    if (patch.type == GroundType::kGravel) gravel.push_back(&patch);
  }
  if (gravel.empty()) return std::nullopt;
  Eigen::Vector2d p = gravel.front()->center_m;
  for (int i = 0; i < 100; ++i) {
    const GroundPatch& patch = *gravel[static_cast<std::size_t>(rng.Index(int(gravel.size())))];
    // Inside 0.6 of the radius: the rim wobbles by 20 % and ragged borders by ~15 cm.
    const double r = 0.6 * patch.radius_m * std::sqrt(rng.Uniform01());
    const double a = rng.Uniform(-kPi, kPi);
    p = patch.center_m + r * Eigen::Vector2d(std::cos(a), std::sin(a));
    if (terrain.GroundAt(p) == GroundType::kGravel && InPark(world, p) &&
        !InsideStructure(world, p)) {
      break;
    }
  }
  return p;
}

}  // namespace

void PlaceLitter(World& world) {
  const LitterSpec& spec = world.spec.litter;
  Rng rng(world.spec.seed, 301);
  // The wear of every item and where items dropped on gravel fall come from streams of their
  // own: a world with none of it draws exactly what it drew before wear existed.
  Rng wear_rng(world.spec.seed, 302), gravel_rng(world.spec.seed, 303);
  Rng clear_rng(world.spec.seed, 304);
  const Sinking sinking{spec.half_hidden_fraction, spec.half_hidden_depth_min,
                        spec.half_hidden_depth_max};
  std::vector<Eigen::Vector2d> hotspots = world.hotspots_m;
  std::vector<double> weights(hotspots.size(), 3.0);
  for (const Eigen::Vector2d& p : PathEdgePoints(world.terrain)) {
    hotspots.push_back(p);
    weights.push_back(1.0);
  }
  double total_weight = 0;
  for (double w : weights) total_weight += w;
  const auto pick_hotspot = [&](Rng& draw_rng) {
    double u = draw_rng.Uniform(0, total_weight);
    for (std::size_t i = 0; i < hotspots.size(); ++i) {
      if ((u -= weights[i]) < 0) return hotspots[i];
    }
    return hotspots.back();
  };
  const auto drop = [&](Rng& draw_rng, const std::string& label) {
    const LitterWear wear = DrawLitterWear(spec, label, wear_rng);
    const std::optional<Eigen::Vector2d> spot =
        wear.on_gravel ? OnGravel(world, gravel_rng) : std::nullopt;
    const bool clustered = !hotspots.empty() && draw_rng.Bernoulli(spec.hotspot_fraction);
    const Eigen::Vector2d center = clustered ? pick_hotspot(draw_rng) : Eigen::Vector2d::Zero();
    PlaceSmall(world, draw_rng, clear_rng, ObjectKind::kLitter, label, sinking, &wear, spot, [&] {
      if (clustered) {
        return Eigen::Vector2d(center.x() + draw_rng.Normal(0, spec.hotspot_sigma_m),
                               center.y() + draw_rng.Normal(0, spec.hotspot_sigma_m));
      }
      return Eigen::Vector2d(draw_rng.Uniform(0, world.spec.size_x_m),
                             draw_rng.Uniform(0, world.spec.size_y_m));
    });
  };
  for (const std::string& label : AllocateLabels(spec.class_weights, spec.count)) drop(rng, label);
  // Later days: some litter picked up, some new dropped.
  for (int day = 1; day <= world.spec.litter_day; ++day) {
    Rng day_rng(world.spec.seed, 1000 + static_cast<std::uint64_t>(day));
    std::erase_if(world.objects, [&](const WorldObject& o) {
      return o.kind == ObjectKind::kLitter && day_rng.Bernoulli(spec.daily_pickup_fraction);
    });
    for (const std::string& label : AllocateLabels(spec.class_weights, spec.daily_new)) {
      drop(day_rng, label);
    }
  }
}

void PlaceNaturalObjects(World& world) {
  Rng rng(world.spec.seed, 401), clear_rng(world.spec.seed, 402);
  std::vector<Eigen::Vector2d> trees;
  for (const WorldObject& o : world.objects) {
    if (o.label == "tree_trunk") trees.push_back(o.center_m.head<2>());
  }
  // Flowers grow in meadow clumps; leaves, cones, branches and mushrooms lie under trees.
  std::vector<Eigen::Vector2d> meadows;
  for (int i = 0; i < 6; ++i) {
    meadows.emplace_back(rng.Uniform(0, world.spec.size_x_m), rng.Uniform(0, world.spec.size_y_m));
  }
  for (const std::string& label :
       AllocateLabels(world.spec.natural.class_weights, world.spec.natural.count)) {
    const bool flower = label.rfind("flower", 0) == 0;
    const bool under_tree = !flower && label != "stone" && !trees.empty();
    const Eigen::Vector2d center =
        flower       ? meadows[static_cast<std::size_t>(rng.Index(int(meadows.size())))]
        : under_tree ? trees[static_cast<std::size_t>(rng.Index(int(trees.size())))]
                     : Eigen::Vector2d(rng.Uniform(0, world.spec.size_x_m),
                                       rng.Uniform(0, world.spec.size_y_m));
    const double sigma = flower ? 1.5 : under_tree ? 2.0 : 0.0;
    PlaceSmall(world, rng, clear_rng, ObjectKind::kNatural, label, Sinking{}, nullptr, std::nullopt,
               [&] {
                 if (sigma == 0) {
                   return Eigen::Vector2d(rng.Uniform(0, world.spec.size_x_m),
                                          rng.Uniform(0, world.spec.size_y_m));
                 }
                 return Eigen::Vector2d(center.x() + rng.Normal(0, sigma),
                                        center.y() + rng.Normal(0, sigma));
               });
  }
}

}  // namespace littermap::sim
