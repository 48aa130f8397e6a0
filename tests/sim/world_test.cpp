// The generated park: determinism, counts and class mix, clustered litter, a clear route.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/error.hpp"
#include "sim/footprint.hpp"
#include "sim/simulation.hpp"
#include "sim/terrain.hpp"
#include "sim/world.hpp"
#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

using test::SampleWorld;

bool SameObjects(const World& a, const World& b) {
  if (a.objects.size() != b.objects.size()) return false;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const WorldObject &x = a.objects[i], &y = b.objects[i];
    if (x.label != y.label || x.center_m != y.center_m || x.size_m != y.size_m ||
        x.colour_rgb != y.colour_rgb || x.orientation.yaw_rad != y.orientation.yaw_rad) {
      return false;
    }
  }
  return true;
}

TEST(World, SameSeedSameWorldOtherSeedOtherWorld) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  const World a = GenerateWorld(spec), b = GenerateWorld(spec);
  EXPECT_TRUE(SameObjects(a, b));
  spec.seed += 1;
  EXPECT_FALSE(SameObjects(a, GenerateWorld(spec)));
}

// park_large has three routes from one dock: driving any of them, with any run seed, is a
// survey of the same park, and every route's corridor is clear.
TEST(World, EveryRouteSurveysTheSameParkAndIsClear) {
  WorldSpec spec = LoadWorldSpec(SampleWorld("park_large.yaml"));
  const World lanes = GenerateWorld(spec);
  spec.driven_route = "perimeter";
  spec.run_seed = 99;
  const World perimeter = GenerateWorld(spec);
  spec.driven_route = "diagonals";
  const World diagonals = GenerateWorld(spec);
  EXPECT_TRUE(SameObjects(lanes, perimeter));
  EXPECT_TRUE(SameObjects(lanes, diagonals));
  EXPECT_NE(lanes.route_m, perimeter.route_m);
  ASSERT_EQ(diagonals.corridors_m.size(), 3u);
  for (const WorldObject& o : diagonals.objects) {
    if (o.kind == ObjectKind::kLitter || o.kind == ObjectKind::kNatural ||
        o.label == "tree_crown") {
      continue;
    }
    for (const auto& corridor : diagonals.corridors_m) {
      for (std::size_t i = 0; i + 1 < corridor.size(); ++i) {
        EXPECT_GT(DistanceToSegment(o.center_m.head<2>(), corridor[i], corridor[i + 1]),
                  spec.structure.route_clearance_m)
            << o.label << " " << o.id;
      }
    }
  }
  spec.driven_route = "lawn";
  try {
    spec.DrivenRoute();
    FAIL() << "accepted an unknown route";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("no route named 'lawn' (routes: route, perimeter, "
                                         "diagonals)"),
              std::string::npos)
        << e.what();
  }
}

TEST(World, TheRunSeedChangesTheSensorsNotThePark) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  const Simulation first(spec, {20});
  spec.run_seed = spec.seed + 1;
  const Simulation second(spec, {20});
  EXPECT_TRUE(SameObjects(first.world(), second.world()));
  ASSERT_EQ(first.states().size(), second.states().size());
  EXPECT_EQ(first.states().back().pose.x_m, second.states().back().pose.x_m);  // same drive
  EXPECT_NE(first.odometry().back().x_m, second.odometry().back().x_m);        // other drift
  EXPECT_NE(first.Scan(50).ranges_m, second.Scan(50).ranges_m);                // other noise
}

// Day by day some litter is picked up and new litter dropped; the rest stays where it was, and
// nothing but litter changes.
TEST(World, LitterChangesFromDayToDay) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  const World day0 = GenerateWorld(spec);
  spec.litter_day = 1;
  const World day1 = GenerateWorld(spec);
  spec.litter_day = 2;
  const World day2 = GenerateWorld(spec);
  const World day2_again = GenerateWorld(spec);
  EXPECT_TRUE(SameObjects(day2, day2_again));

  const auto litter = [](const World& world) {
    std::vector<Eigen::Vector3d> centres;
    for (const WorldObject& o : world.objects) {
      if (o.kind == ObjectKind::kLitter) centres.push_back(o.center_m);
    }
    return centres;
  };
  const auto kept = [](const std::vector<Eigen::Vector3d>& before,
                       const std::vector<Eigen::Vector3d>& after) {
    return std::count_if(before.begin(), before.end(), [&](const Eigen::Vector3d& p) {
      return std::find(after.begin(), after.end(), p) != after.end();
    });
  };
  const auto litter0 = litter(day0), litter1 = litter(day1), litter2 = litter(day2);
  // 60 items, 30 % picked up (binomial: 42 +- 3.6 kept), 10 new.
  EXPECT_NEAR(static_cast<double>(kept(litter0, litter1)), 42.0, 11.0);
  EXPECT_EQ(static_cast<std::ptrdiff_t>(litter1.size()), kept(litter0, litter1) + 10);
  EXPECT_EQ(static_cast<std::ptrdiff_t>(litter2.size()), kept(litter1, litter2) + 10);
  EXPECT_EQ(day1.Count(ObjectKind::kNatural), day0.Count(ObjectKind::kNatural));
  EXPECT_EQ(day1.Count(ObjectKind::kTree), day0.Count(ObjectKind::kTree));
}

TEST(World, CountsAndClassMixMatchTheSpec) {
  const WorldSpec spec = LoadWorldSpec(SampleWorld());
  const World world = GenerateWorld(spec);
  EXPECT_EQ(world.Count(ObjectKind::kLitter), 60u);
  EXPECT_EQ(world.Count(ObjectKind::kNatural), 80u);
  EXPECT_EQ(world.Count(ObjectKind::kBin), 3u);
  EXPECT_EQ(world.Count(ObjectKind::kBench), 4u * 4);  // seat, back, two legs
  EXPECT_GE(world.Count(ObjectKind::kTree), 2u * 20);  // trunk + crown; a few may not fit
  std::map<std::string, int> classes;
  for (const WorldObject& o : world.objects) {
    if (o.kind == ObjectKind::kLitter) ++classes[o.label];
  }
  // Largest-remainder allocation: weight × 60 exactly (the weights give whole numbers).
  const std::map<std::string, int> expected = {
      {"bottle", 12},        {"can", 9},   {"carton", 6},     {"cup", 9},
      {"food_container", 6}, {"other", 9}, {"plastic_bag", 9}};
  EXPECT_EQ(classes, expected);
}

TEST(World, LitterIsDenserNearBenchesAndBins) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  spec.litter.count = 600;  // enough items for a stable density ratio
  const World world = GenerateWorld(spec);
  constexpr double kNearM = 3;
  const auto near = [&](const Eigen::Vector2d& p) {
    for (const WorldObject& o : world.objects) {
      if ((o.label == "bench_seat" || o.kind == ObjectKind::kBin) &&
          (p - o.center_m.head<2>()).norm() < kNearM) {
        return true;
      }
    }
    return false;
  };
  // Areas by a 10 cm grid.
  double near_area = 0, far_area = 0;
  for (double x = 0.05; x < spec.size_x_m; x += 0.1) {
    for (double y = 0.05; y < spec.size_y_m; y += 0.1)
      (near({x, y}) ? near_area : far_area) += 0.01;
  }
  int near_count = 0, far_count = 0;
  for (const WorldObject& o : world.objects) {
    if (o.kind == ObjectKind::kLitter) ++(near(o.center_m.head<2>()) ? near_count : far_count);
  }
  const double ratio = (near_count / near_area) / (far_count / far_area);
  // Expected about 10x with 3/4 of the litter around hotspots; 4x is the stated lower bound.
  EXPECT_GT(ratio, 4.0) << near_count << " near in " << near_area << " m², " << far_count
                        << " elsewhere in " << far_area << " m²";
}

// Litter and look-alikes lie side by side, never through each other (two bottles 1.5 cm apart
// were one item to any detector), on every seed and day, and in a park crowded with them.
TEST(World, SmallObjectsNeverShareSpace) {
  WorldSpec spec = LoadWorldSpec(SampleWorld());
  for (const int seed : {7, 21, 101, 76}) {
    for (const int day : {0, 2}) {
      spec.seed = static_cast<std::uint64_t>(seed);
      spec.litter_day = day;
      spec.litter.count = seed == 76 ? 600 : 60;
      const World world = GenerateWorld(spec);
      std::vector<const WorldObject*> small;
      for (const WorldObject& o : world.objects) {
        if (o.kind == ObjectKind::kLitter || o.kind == ObjectKind::kNatural) small.push_back(&o);
      }
      for (std::size_t i = 0; i < small.size(); ++i) {
        for (std::size_t j = i + 1; j < small.size(); ++j) {
          EXPECT_FALSE(FootprintsOverlap(FootprintOf(*small[i]), FootprintOf(*small[j]), 0.0))
              << "seed " << seed << " day " << day << ": " << small[i]->label << " " << small[i]->id
              << " and " << small[j]->label << " " << small[j]->id;
        }
      }
    }
  }
}

TEST(World, StructureKeepsTheRouteClear) {
  const WorldSpec spec = LoadWorldSpec(SampleWorld());
  const World world = GenerateWorld(spec);
  for (const WorldObject& o : world.objects) {
    if (o.kind == ObjectKind::kLitter || o.kind == ObjectKind::kNatural ||
        o.label == "tree_crown") {
      continue;
    }
    for (std::size_t i = 0; i + 1 < world.route_m.size(); ++i) {
      const double d =
          DistanceToSegment(o.center_m.head<2>(), world.route_m[i], world.route_m[i + 1]);
      EXPECT_GT(d, spec.structure.route_clearance_m) << o.label << " " << o.id;
    }
  }
}

TEST(Terrain, GradientMatchesFiniteDifferencesAndBound) {
  const WorldSpec spec = LoadWorldSpec(SampleWorld());
  const Terrain terrain(spec, spec.seed);
  for (double x = 1; x < 40; x += 3.7) {
    for (double y = 1; y < 30; y += 2.9) {
      const Eigen::Vector2d p(x, y), dx(1e-5, 0), dy(0, 1e-5);
      const Eigen::Vector2d g = terrain.GradientAt(p);
      EXPECT_NEAR(g.x(), (terrain.HeightAt(p + dx) - terrain.HeightAt(p - dx)) / 2e-5, 1e-6);
      EXPECT_NEAR(g.y(), (terrain.HeightAt(p + dy) - terrain.HeightAt(p - dy)) / 2e-5, 1e-6);
      EXPECT_LE(g.norm(), terrain.max_slope());
    }
  }
  EXPECT_EQ(terrain.GroundAt({20, 14.25}), GroundType::kDirtPath);  // on the sample's path
  EXPECT_EQ(terrain.GroundAt({20, 12.5}), GroundType::kGrass);
}

}  // namespace
}  // namespace littermap::sim
