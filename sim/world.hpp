#pragma once
// The simulated park: terrain plus every object in it, each a simple 3D primitive with a class,
// size, colour and texture class, so the laser can ray-cast it now and a renderer can draw it
// later. Generated from the WorldSpec's seed with independent random streams per object family.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/pose3.hpp"
#include "sim/terrain.hpp"
#include "sim/world_spec.hpp"

namespace littermap::sim {

enum class ObjectKind { kTree, kRock, kBench, kBin, kFence, kBush, kLitter, kNatural };
const char* ObjectKindName(ObjectKind kind);

// Primitives in the object's own frame, centred on its origin: a cylinder along local z
// (size x = y = diameter, z = height), a box, an ellipsoid (size = diameters).
enum class Shape { kCylinder, kBox, kEllipsoid };
const char* ShapeName(Shape shape);

struct WorldObject {
  int id = 0;
  int group = -1;  // id of the first primitive of a multi-part object (bench: seat, back, legs)
  ObjectKind kind = ObjectKind::kTree;
  std::string label;  // class: "tree_trunk", "bench_seat", "can", "flower_red", ...
  Shape shape = Shape::kBox;
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  RollPitchYaw orientation;
  Eigen::Vector3d size_m = Eigen::Vector3d::Ones();
  Eigen::Vector3d colour_rgb = Eigen::Vector3d::Constant(0.5);  // linear 0..1
  std::string texture;         // "bark", "leaves", "stone", "wood", "metal", "plastic", ...
  double hidden_fraction = 0;  // share hidden in grass (litter and natural objects)
  // Wear that makes litter hard to see (sim/litter_wear.hpp); all 0 / false: as made.
  double dirt = 0;          // wet soil on it: 0 clean .. 1 caked (darker, greyer, browner)
  double transmission = 0;  // clear plastic: share of the light from behind passing through
  bool crushed = false;     // a can flattened (its size_m is the crushed size)
  double size() const { return size_m.maxCoeff(); }  // largest extent
};

struct World {
  WorldSpec spec;
  Terrain terrain;
  std::vector<WorldObject> objects;
  std::vector<Eigen::Vector2d> route_m;  // the planned route the robot drives
  // Every route of the spec, planned: the structure keeps clear of all of them, so the world is
  // the same whichever one is driven.
  std::vector<std::vector<Eigen::Vector2d>> corridors_m;
  std::vector<Eigen::Vector2d> hotspots_m;    // where litter accumulates (benches, bins, paths)
  std::vector<Eigen::Vector2d> open_areas_m;  // centres of the structure-free disks

  std::size_t Count(ObjectKind kind) const;
};

// Generates the world of `spec` (spec.seed). Deterministic across platforms.
World GenerateWorld(const WorldSpec& spec);

// Adds one primitive to `world` and returns its id.
int AddObject(World& world, WorldObject object);

// Litter and natural look-alikes (sim/litter_placement.cpp).
void PlaceLitter(World& world);
void PlaceNaturalObjects(World& world);

}  // namespace littermap::sim
