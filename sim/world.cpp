#include "sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/random.hpp"
#include "sim/route.hpp"

namespace littermap::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxTries = 300;

struct Footprint {
  Eigen::Vector2d center_m;
  double radius_m;
};

// Where structure may stand: inside the park, off the route corridor, paths and open areas,
// and not on top of other structure.
class Placer {
 public:
  Placer(World& world, Rng& rng) : world_(world), rng_(rng) {}

  bool Free(const Eigen::Vector2d& p, double radius_m, bool allow_path_edge = false) const {
    const WorldSpec& spec = world_.spec;
    if (p.x() < radius_m || p.y() < radius_m || p.x() > spec.size_x_m - radius_m ||
        p.y() > spec.size_y_m - radius_m) {
      return false;
    }
    const double clearance = spec.structure.route_clearance_m + radius_m;
    for (const std::vector<Eigen::Vector2d>& corridor : world_.corridors_m) {
      for (std::size_t i = 0; i + 1 < corridor.size(); ++i) {
        if (DistanceToSegment(p, corridor[i], corridor[i + 1]) < clearance) return false;
      }
    }
    if (!allow_path_edge && world_.terrain.DistanceToPathEdge(p) < radius_m + 0.3) return false;
    for (const Eigen::Vector2d& open : world_.open_areas_m) {
      if ((p - open).norm() < spec.structure.open_area_radius_m + radius_m) return false;
    }
    return std::none_of(taken_.begin(), taken_.end(), [&](const Footprint& f) {
      return (p - f.center_m).norm() < f.radius_m + radius_m + 0.3;
    });
  }
  // A free spot drawn by `draw`, or false after kMaxTries attempts.
  template <typename Draw>
  bool Find(double radius_m, Draw draw, Eigen::Vector2d& out, bool allow_path_edge = false) {
    for (int i = 0; i < kMaxTries; ++i) {
      out = draw();
      if (Free(out, radius_m, allow_path_edge)) {
        taken_.push_back({out, radius_m});
        return true;
      }
    }
    return false;
  }
  Eigen::Vector2d Anywhere() {
    return {rng_.Uniform(0, world_.spec.size_x_m), rng_.Uniform(0, world_.spec.size_y_m)};
  }
  // A point beside a random path, `offset_m` from its edge; the heading faces the path.
  Eigen::Vector2d BesidePath(double offset_m, double& facing_rad) {
    const auto& paths = world_.terrain.paths();
    const PathSpec& path = paths[static_cast<std::size_t>(rng_.Index(int(paths.size())))];
    const std::size_t i = static_cast<std::size_t>(rng_.Index(int(path.points_m.size()) - 1));
    const Eigen::Vector2d a = path.points_m[i], b = path.points_m[i + 1];
    const Eigen::Vector2d along = (b - a).normalized();
    const double side = rng_.Bernoulli(0.5) ? 1 : -1;
    const Eigen::Vector2d normal(-along.y() * side, along.x() * side);
    facing_rad = std::atan2(-normal.y(), -normal.x());
    return a + rng_.Uniform01() * (b - a) + normal * (0.5 * path.width_m + offset_m);
  }

 private:
  World& world_;
  Rng& rng_;
  std::vector<Footprint> taken_;
};

WorldObject Primitive(ObjectKind kind, const char* label, Shape shape, Eigen::Vector3d center,
                      Eigen::Vector3d size, Eigen::Vector3d colour, const char* texture) {
  WorldObject o;
  o.kind = kind;
  o.label = label;
  o.shape = shape;
  o.center_m = center;
  o.size_m = size;
  o.colour_rgb = colour;
  o.texture = texture;
  return o;
}

double Ground(const World& w, const Eigen::Vector2d& p) { return w.terrain.HeightAt(p); }

void AddTrees(World& w, Placer& placer, Rng& rng) {
  for (int i = 0; i < w.spec.structure.trees; ++i) {
    const double radius = rng.Uniform(0.1, 0.45);
    Eigen::Vector2d p;
    if (!placer.Find(
            radius, [&] { return placer.Anywhere(); }, p))
      continue;
    const double trunk_h = rng.Uniform(2.5, 4.0), crown = rng.Uniform(1.5, 3.5);
    const double z = Ground(w, p) - 0.1;  // trunks go into the ground
    const int id =
        AddObject(w, Primitive(ObjectKind::kTree, "tree_trunk", Shape::kCylinder,
                               {p.x(), p.y(), z + trunk_h / 2}, {2 * radius, 2 * radius, trunk_h},
                               {0.33, 0.25, 0.18}, "bark"));
    WorldObject top = Primitive(ObjectKind::kTree, "tree_crown", Shape::kEllipsoid,
                                {p.x(), p.y(), z + trunk_h + 0.7 * crown},
                                {2 * crown, 2 * crown, 1.6 * crown}, {0.2, 0.45, 0.15}, "leaves");
    top.group = id;
    AddObject(w, top);
  }
}

void AddBlobs(World& w, Placer& placer, Rng& rng, bool rocks) {
  const int count = rocks ? w.spec.structure.rocks : w.spec.structure.bushes;
  for (int i = 0; i < count; ++i) {
    const double rx = rocks ? rng.Uniform(0.2, 0.7) : rng.Uniform(0.5, 1.2);
    const double ry = rx * rng.Uniform(0.6, 1.0);
    const double rz = rocks ? rng.Uniform(0.15, 0.5) : rng.Uniform(0.4, 0.9);
    Eigen::Vector2d p;
    if (!placer.Find(
            rx, [&] { return placer.Anywhere(); }, p))
      continue;
    const double grey = rng.Uniform(0.4, 0.65);
    WorldObject o = Primitive(
        rocks ? ObjectKind::kRock : ObjectKind::kBush, rocks ? "rock" : "bush", Shape::kEllipsoid,
        {p.x(), p.y(), Ground(w, p) + (rocks ? 0.3 : 0.7) * rz}, {2 * rx, 2 * ry, 2 * rz},
        rocks ? Eigen::Vector3d(grey, grey, grey * 0.95) : Eigen::Vector3d(0.15, 0.4, 0.12),
        rocks ? "stone" : "leaves");
    o.orientation.yaw_rad = rng.Uniform(-kPi, kPi);
    AddObject(w, o);
  }
}

// A bench: seat, backrest and two leg frames; its front (local +x) faces heading `yaw`.
void AddBench(World& w, const Eigen::Vector2d& p, double yaw) {
  const double g = Ground(w, p);
  const Eigen::Vector3d wood(0.45, 0.3, 0.15), metal(0.2, 0.2, 0.2);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const auto at = [&](double fx, double fy, double z) {
    const Eigen::Vector2d q = p + R * Eigen::Vector2d(fx, fy);
    return Eigen::Vector3d(q.x(), q.y(), g + z);
  };
  // Local frame: x towards the path (front), y along the bench.
  std::vector<WorldObject> parts = {
      Primitive(ObjectKind::kBench, "bench_seat", Shape::kBox, at(0, 0, 0.45), {0.45, 1.6, 0.06},
                wood, "wood"),
      Primitive(ObjectKind::kBench, "bench_back", Shape::kBox, at(-0.22, 0, 0.72), {0.05, 1.6, 0.4},
                wood, "wood"),
      Primitive(ObjectKind::kBench, "bench_leg", Shape::kBox, at(0, -0.7, 0.21), {0.45, 0.06, 0.42},
                metal, "metal"),
      Primitive(ObjectKind::kBench, "bench_leg", Shape::kBox, at(0, 0.7, 0.21), {0.45, 0.06, 0.42},
                metal, "metal")};
  int group = -1;
  for (WorldObject& part : parts) {
    part.orientation.yaw_rad = yaw;
    part.group = group;
    const int id = AddObject(w, part);
    if (group < 0) group = id;
  }
}

void AddBenchesAndBins(World& w, Placer& placer, Rng& rng) {
  const bool paths = !w.terrain.paths().empty();
  double yaw = 0;
  for (int i = 0; i < w.spec.structure.benches; ++i) {
    Eigen::Vector2d p;
    const auto draw = [&] {
      if (paths) return placer.BesidePath(rng.Uniform(0.6, 1.2), yaw);
      yaw = rng.Uniform(-kPi, kPi);
      return placer.Anywhere();
    };
    if (!placer.Find(0.9, draw, p, paths)) continue;
    AddBench(w, p, yaw);
    w.hotspots_m.push_back(p);
  }
  for (int i = 0; i < w.spec.structure.bins; ++i) {
    Eigen::Vector2d p;
    const auto draw = [&] { return paths ? placer.BesidePath(0.5, yaw) : placer.Anywhere(); };
    if (!placer.Find(0.3, draw, p, paths)) continue;
    AddObject(
        w, Primitive(ObjectKind::kBin, "bin", Shape::kCylinder, {p.x(), p.y(), Ground(w, p) + 0.45},
                     {0.5, 0.5, 0.9}, {0.1, 0.35, 0.15}, "metal"));
    w.hotspots_m.push_back(p);
  }
}

void AddFences(World& w, Placer& placer, Rng& rng) {
  const double sx = w.spec.size_x_m, sy = w.spec.size_y_m;
  for (int i = 0; i < w.spec.structure.fence_segments; ++i) {
    const double length = rng.Uniform(4, 10);
    const bool wall = rng.Bernoulli(0.3);
    const int edge = rng.Index(4);  // 0 south, 1 east, 2 north, 3 west
    const bool along_x = edge % 2 == 0;
    const double t = rng.Uniform(length / 2 + 0.5, (along_x ? sx : sy) - length / 2 - 0.5);
    const double inset = 0.6;
    Eigen::Vector2d p = along_x ? Eigen::Vector2d(t, edge == 0 ? inset : sy - inset)
                                : Eigen::Vector2d(edge == 1 ? sx - inset : inset, t);
    if (!placer.Find(
            0.3, [&] { return p; }, p, true))
      continue;
    const double height = wall ? 1.5 : 1.0;
    WorldObject o = Primitive(
        ObjectKind::kFence, wall ? "wall" : "fence", Shape::kBox,
        {p.x(), p.y(), Ground(w, p) + height / 2 - 0.1}, {length, wall ? 0.25 : 0.06, height},
        wall ? Eigen::Vector3d(0.6, 0.55, 0.5) : Eigen::Vector3d(0.4, 0.3, 0.2),
        wall ? "stone" : "wood");
    o.orientation.yaw_rad = along_x ? 0 : kPi / 2;
    AddObject(w, o);
  }
}

}  // namespace

const char* ObjectKindName(ObjectKind kind) {
  static const char* const kNames[] = {"tree",  "rock", "bench",  "bin",
                                       "fence", "bush", "litter", "natural"};
  return kNames[static_cast<int>(kind)];
}

const char* ShapeName(Shape shape) {
  static const char* const kNames[] = {"cylinder", "box", "ellipsoid"};
  return kNames[static_cast<int>(shape)];
}

std::size_t World::Count(ObjectKind kind) const {
  return static_cast<std::size_t>(std::count_if(
      objects.begin(), objects.end(), [&](const WorldObject& o) { return o.kind == kind; }));
}

int AddObject(World& world, WorldObject object) {
  object.id = static_cast<int>(world.objects.size());
  if (object.group < 0) object.group = object.id;
  world.objects.push_back(std::move(object));
  return world.objects.back().id;
}

World GenerateWorld(const WorldSpec& spec) {
  World world{spec, Terrain(spec, spec.seed), {}, PlanRoute(spec.DrivenRoute()), {}, {}, {}};
  world.corridors_m.push_back(PlanRoute(spec.route));
  for (const auto& [name, route] : spec.routes) world.corridors_m.push_back(PlanRoute(route));
  Rng rng(spec.seed, 201);
  for (int i = 0; i < spec.structure.open_areas; ++i) {
    world.open_areas_m.emplace_back(rng.Uniform(0, spec.size_x_m), rng.Uniform(0, spec.size_y_m));
  }
  Placer placer(world, rng);
  AddFences(world, placer, rng);
  AddBenchesAndBins(world, placer, rng);
  AddTrees(world, placer, rng);
  AddBlobs(world, placer, rng, true);
  AddBlobs(world, placer, rng, false);
  PlaceLitter(world);
  PlaceNaturalObjects(world);
  return world;
}

}  // namespace littermap::sim
