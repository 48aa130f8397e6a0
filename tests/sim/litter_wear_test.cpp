// Hard-to-see litter in the generated park (sim/litter_wear.hpp): wear draws leave everything
// else in place, crushed cans are flat, sunk items sink as deep as asked, items meant for gravel
// lie on it, and park_hard.yaml has the shares it promises.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/ground_map.hpp"
#include "sim/world.hpp"
#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

using test::SampleWorld;

// Three binomial standard deviations of a share of n draws with probability p: the tolerance of
// every share below (a fixed seed passes or fails for good, 3σ keeps a fair seed inside).
double ThreeSigma(double p, int n) { return 3 * std::sqrt(p * (1 - p) / std::max(n, 1)); }

// Vertical extent of an object's oriented bounding box: exact for a cylinder standing or lying.
double Height(const WorldObject& o) {
  const Eigen::Matrix3d R = RotationFromRpy(o.orientation);
  return R.row(2).cwiseAbs().dot(o.size_m);
}

std::vector<const WorldObject*> Litter(const World& world, const std::string& label = "") {
  std::vector<const WorldObject*> items;
  for (const WorldObject& o : world.objects) {
    if (o.kind == ObjectKind::kLitter && (label.empty() || o.label == label)) items.push_back(&o);
  }
  return items;
}

// Sun of the camera's defaults (sim/rgbd_camera.hpp: 50° up, azimuth 35°), for shade.
Eigen::Vector3d DefaultSun() {
  const double deg = std::numbers::pi / 180;
  return {std::cos(50 * deg) * std::cos(35 * deg), std::cos(50 * deg) * std::sin(35 * deg),
          std::sin(50 * deg)};
}

TEST(LitterWear, WearDrawsLeaveEverythingElseInPlace) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  const World plain = GenerateWorld(spec);
  spec.litter.dirty_fraction = 0.5;
  spec.litter.crushed_fraction = 1;
  spec.litter.clear_bottle_fraction = 1;
  spec.litter.on_gravel_fraction = 0.3;
  const World worn = GenerateWorld(spec);
  ASSERT_EQ(plain.objects.size(), worn.objects.size());
  int dirty = 0, crushed = 0, clear = 0, moved = 0;
  for (std::size_t i = 0; i < plain.objects.size(); ++i) {
    const WorldObject &a = plain.objects[i], &b = worn.objects[i];
    EXPECT_EQ(a.label, b.label);
    EXPECT_EQ(a.orientation.yaw_rad, b.orientation.yaw_rad);
    EXPECT_EQ(a.orientation.pitch_rad, b.orientation.pitch_rad);
    EXPECT_EQ(a.dirt, 0);
    EXPECT_EQ(a.transmission, 0);
    EXPECT_FALSE(a.crushed);
    dirty += b.dirt > 0;
    crushed += b.crushed;
    clear += b.transmission > 0;
    if (a.center_m.head<2>() != b.center_m.head<2>()) {  // dropped on gravel instead, unsunk
      ++moved;
      EXPECT_EQ(b.kind, ObjectKind::kLitter);
      EXPECT_EQ(worn.terrain.GroundAt(b.center_m.head<2>()), GroundType::kGravel);
      EXPECT_EQ(b.hidden_fraction, 0);
      continue;
    }
    EXPECT_EQ(a.hidden_fraction, b.hidden_fraction);
    if (!b.crushed) {
      EXPECT_EQ(a.center_m, b.center_m);
      EXPECT_EQ(a.size_m, b.size_m);
    }
    if (b.transmission == 0) {
      EXPECT_EQ(a.colour_rgb, b.colour_rgb);
    }
    if (b.kind != ObjectKind::kLitter) {
      EXPECT_EQ(b.dirt, 0);
    }
  }
  const int items = static_cast<int>(Litter(plain).size());
  EXPECT_NEAR(double(dirty) / items, 0.5, ThreeSigma(0.5, items));
  EXPECT_NEAR(double(moved) / items, 0.3, ThreeSigma(0.3, items));
  EXPECT_EQ(crushed, static_cast<int>(Litter(plain, "can").size()));
  EXPECT_EQ(clear, static_cast<int>(Litter(plain, "bottle").size()));
}

TEST(LitterWear, CrushedCansAreFlatAndOnTheGround) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  spec.litter.count = 400;
  spec.litter.class_weights = {{"can", 1.0}};
  spec.litter.crushed_fraction = 0.5;
  spec.litter.half_hidden_fraction = 0;
  const World world = GenerateWorld(spec);
  const std::vector<const WorldObject*> cans = Litter(world, "can");
  ASSERT_EQ(cans.size(), 400u);
  int crushed = 0;
  for (const WorldObject* can : cans) {
    const bool lying = std::abs(can->orientation.pitch_rad) > 1;
    const double made = lying ? 0.066 : 0.12;  // height of the can as made
    const double height = Height(*can);
    const double ground = world.terrain.HeightAt(can->center_m.head<2>());
    // Resting on the ground: the bottom within rounding of the terrain.
    EXPECT_NEAR(can->center_m.z() - 0.5 * height, ground, 1e-9);
    if (can->crushed) {
      ++crushed;
      EXPECT_LE(height, 0.4 * made + 1e-12);  // flattened to 20-40 %
      EXPECT_GE(height, 0.2 * made - 1e-12);
      EXPECT_LE(height, 0.05);  // under 5 cm: lower than any can standing or lying
    } else {
      EXPECT_NEAR(height, made, 1e-12);
    }
  }
  EXPECT_NEAR(crushed / 400.0, 0.5, ThreeSigma(0.5, 400));
}

TEST(LitterWear, SunkItemsSinkAsDeepAsAsked) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  spec.litter.count = 300;
  spec.litter.half_hidden_fraction = 1;
  spec.litter.half_hidden_depth_min = 0.7;
  spec.litter.half_hidden_depth_max = 0.8;
  const World world = GenerateWorld(spec);
  int on_grass = 0;
  for (const WorldObject* o : Litter(world)) {
    if (world.terrain.GroundAt(o->center_m.head<2>()) == GroundType::kGrass) {
      ++on_grass;
      EXPECT_GE(o->hidden_fraction, 0.7);
      EXPECT_LE(o->hidden_fraction, 0.8);
    } else {
      EXPECT_EQ(o->hidden_fraction, 0);  // only grass hides things
    }
  }
  EXPECT_GT(on_grass, 100);
}

TEST(LitterWear, ItemsForGravelLieOnGravel) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  spec.litter.count = 200;
  spec.litter.on_gravel_fraction = 1;
  const World world = GenerateWorld(spec);
  const GroundMap ground(world, DefaultSun());  // the renderer's ragged ground regions
  int on_gravel = 0;
  const std::vector<const WorldObject*> items = Litter(world);
  for (const WorldObject* o : items) {
    const Eigen::Vector2d p = o->center_m.head<2>();
    on_gravel += world.terrain.GroundAt(p) == GroundType::kGravel &&
                 ground.TypeAt(float(p.x()), float(p.y())) == GroundType::kGravel;
  }
  // A few may be pushed off by a structure standing on the gravel (100 tries) or by a path.
  EXPECT_GE(double(on_gravel) / double(items.size()), 0.95);
}

TEST(LitterWear, ParkHardHasTheHardLitterItPromises) {
  const WorldSpec spec = LoadWorldSpec(SampleWorld("park_hard.yaml"));
  const World world = GenerateWorld(spec);
  const GroundMap ground(world, DefaultSun());
  const std::vector<const WorldObject*> items = Litter(world);
  const int n = static_cast<int>(items.size());
  ASSERT_EQ(n, 70);
  int dirty = 0, on_grass = 0, sunk = 0, on_gravel = 0, shaded = 0;
  for (const WorldObject* o : items) {
    const Eigen::Vector2d p = o->center_m.head<2>();
    dirty += o->dirt > 0;
    const bool grass = world.terrain.GroundAt(p) == GroundType::kGrass;
    on_grass += grass;
    sunk += grass && o->hidden_fraction > 0;
    if (o->hidden_fraction > 0) {
      EXPECT_GE(o->hidden_fraction, 0.4);
    }
    on_gravel += world.terrain.GroundAt(p) == GroundType::kGravel;
    // Tree shade passes 10-40 % of the sun; cloud shade alone never goes below 55 %.
    shaded += ground.SunlightAt(float(p.x()), float(p.y())) < 0.5f;
  }
  EXPECT_NEAR(double(dirty) / n, 0.4, ThreeSigma(0.4, n));
  EXPECT_NEAR(double(sunk) / on_grass, 0.4, ThreeSigma(0.4, on_grass));
  // A quarter is dropped on gravel; litter gathering by paths and benches adds some more.
  EXPECT_GE(double(on_gravel) / n, 0.25 - ThreeSigma(0.25, n));
  // 45 trees: most of the litter lies in shade (park_small, 25 trees: 42 %). Measured 56 %.
  EXPECT_GE(double(shaded) / n, 0.5);
  int crushed = 0, clear = 0;
  const auto cans = Litter(world, "can"), bottles = Litter(world, "bottle");
  for (const WorldObject* can : cans) crushed += can->crushed;
  for (const WorldObject* bottle : bottles) clear += bottle->transmission > 0;
  const int n_cans = static_cast<int>(cans.size()), n_bottles = static_cast<int>(bottles.size());
  EXPECT_NEAR(double(crushed) / n_cans, 0.5, ThreeSigma(0.5, n_cans));
  EXPECT_NEAR(double(clear) / n_bottles, 0.6, ThreeSigma(0.6, n_bottles));
  // Look-alikes: mostly red and white flowers and mushrooms (weights 0.58 of the total).
  int red_white = 0, natural = 0;
  for (const WorldObject& o : world.objects) {
    if (o.kind != ObjectKind::kNatural) continue;
    ++natural;
    red_white += o.label == "flower_red" || o.label == "flower_white" || o.label == "mushroom";
  }
  EXPECT_NEAR(double(red_white) / natural, 0.58, 0.02);  // exact allocation, rounding only
}

}  // namespace
}  // namespace littermap::sim
