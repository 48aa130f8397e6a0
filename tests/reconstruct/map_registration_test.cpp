// Map registration and map files: a room's map found again under a known offset, a different
// room refused, and the map_server files read back as they were written.

#include "reconstruct/map_registration.hpp"

#include <cmath>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "reconstruct/occupancy_grid.hpp"
#include "reconstruct/occupancy_map_file.hpp"
#include "support/temp_dir.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

// Points every 5 cm along the walls, with Gaussian noise.
Points2 WallPoints(const std::vector<test::Segment>& walls, double noise_m, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> noise(0, noise_m);
  Points2 points;
  for (const test::Segment& wall : walls) {
    const double length = (wall.b - wall.a).norm();
    for (double s = 0; s <= length; s += 0.05) {
      points.push_back(wall.a + (wall.b - wall.a) * (s / length) +
                       Eigen::Vector2d(noise(engine), noise(engine)));
    }
  }
  return points;
}

// The room as a run's map whose frame sits at T_site_run in the site frame, with noise drawn
// apart from the site map's (seed 1).
Points2 RoomMappedFrom(const PlanarPose& T_site_run) {
  Points2 run = WallPoints(test::Room(), 0.01, 2);
  for (Eigen::Vector2d& p : run) p = Transform(Inverse(T_site_run), p);
  return run;
}

// A long corridor: it does not fit in the room anywhere.
Points2 Corridor() {
  return WallPoints({{{0, 0}, {30, 0}}, {{0, 2}, {30, 2}}, {{0, 0}, {0, 2}}}, 0.01, 2);
}

TEST(MapRegistration, FindsARunMapUnderAKnownOffset) {
  const Points2 site = WallPoints(test::Room(), 0.01, 1);
  const PlanarPose T_site_run{1.3, -0.8, 0.14};  // 8 degrees
  const Points2 run = RoomMappedFrom(T_site_run);
  const MapRegistrationResult result = RegisterMap(site, run, {}, {});
  ASSERT_TRUE(result.registered) << result.matching_ratio;
  EXPECT_NEAR(result.T_site_run.x_m, T_site_run.x_m, 0.02);
  EXPECT_NEAR(result.T_site_run.y_m, T_site_run.y_m, 0.02);
  EXPECT_NEAR(result.T_site_run.theta_rad, T_site_run.theta_rad, 0.005);
  EXPECT_GT(result.matching_ratio, 0.95);
}

TEST(MapRegistration, ARunThatMapsMoreThanTheSiteIsJudgedWhereTheyOverlap) {
  // The site map knows the west part of the room (x < 6 m); the run mapped all of it.
  Points2 site;
  for (const Eigen::Vector2d& p : WallPoints(test::Room(), 0.01, 1)) {
    if (p.x() < 6) site.push_back(p);
  }
  const PlanarPose T_site_run{0.6, 0.4, 0.05};
  const Points2 run = RoomMappedFrom(T_site_run);
  const auto known = [](const Eigen::Vector2d& p) { return p.x() < 6; };
  const MapRegistrationResult overlap = RegisterMap(site, run, {}, {}, known);
  ASSERT_TRUE(overlap.registered) << overlap.matching_ratio;
  EXPECT_GT(overlap.matching_ratio, 0.95);
  EXPECT_NEAR(overlap.T_site_run.x_m, T_site_run.x_m, 0.03);
  EXPECT_NEAR(overlap.T_site_run.y_m, T_site_run.y_m, 0.03);
  // Counted over the whole run map, the east half would have looked like a mismatch.
  EXPECT_LT(RegisterMap(site, run, {}, {}).matching_ratio, 0.7);
}

TEST(MapRegistration, IcpThatStopsShortOfConvergenceIsJudgedByTheMatchingRatio) {
  // Two iterations per stage and a convergence test no step passes: ICP never reports
  // convergence, yet the coarse match it refines is right, and a different place stays refused.
  MapRegistrationOptions options;
  options.icp.max_iterations_per_stage = 2;
  options.icp.convergence_translation_m = 1e-15;
  options.icp.convergence_rotation_rad = 1e-15;
  const Points2 site = WallPoints(test::Room(), 0.01, 1);
  const PlanarPose T_site_run{1.3, -0.8, 0.14};
  const Points2 run = RoomMappedFrom(T_site_run);
  const MapRegistrationResult result = RegisterMap(site, run, {}, options);
  EXPECT_FALSE(result.icp_converged);
  ASSERT_TRUE(result.registered) << result.matching_ratio;
  EXPECT_NEAR(result.T_site_run.x_m, T_site_run.x_m, 0.03);
  EXPECT_NEAR(result.T_site_run.y_m, T_site_run.y_m, 0.03);
  EXPECT_NEAR(result.T_site_run.theta_rad, T_site_run.theta_rad, 0.01);
  EXPECT_GT(result.matching_ratio, 0.9);

  EXPECT_FALSE(RegisterMap(site, Corridor(), {}, options).registered);
}

TEST(MapRegistration, RefusesADifferentPlace) {
  const MapRegistrationResult result =
      RegisterMap(WallPoints(test::Room(), 0.01, 1), Corridor(), {}, {});
  EXPECT_FALSE(result.registered);
  EXPECT_LT(result.matching_ratio, 0.5);
}

TEST(OccupancyMapFile, ReadsBackWhatTheGridWrote) {
  test::TempDir dir;
  OccupancyGrid grid({});
  const Points2 hits = {{2.0, 1.0}, {2.0, 1.05}, {-1.0, 3.0}};
  grid.InsertScan({0, 0}, hits);
  grid.InsertScan({0, 0}, hits);
  grid.WritePgmYaml(dir / "map.pgm", dir / "map.yaml");
  const OccupancyImage map = ReadOccupancyMap(dir / "map.yaml");
  EXPECT_EQ(map.width, grid.width());
  EXPECT_EQ(map.height, grid.height());
  EXPECT_DOUBLE_EQ(map.resolution_m, 0.05);
  const Points2 occupied = OccupiedCellCentres(map);
  ASSERT_EQ(occupied.size(), hits.size());
  for (const Eigen::Vector2d& hit : hits) {
    bool found = false;
    for (const Eigen::Vector2d& p : occupied) found = found || (p - hit).norm() < 0.05;
    EXPECT_TRUE(found) << hit.transpose();
  }
}

TEST(OccupancyMapFile, BadFilesNameTheFileAndField) {
  test::TempDir dir;
  std::ofstream(dir / "no_resolution.yaml") << "image: map.pgm\norigin: [0, 0, 0]\n";
  try {
    ReadOccupancyMap(dir / "no_resolution.yaml");
    FAIL() << "accepted a map without resolution";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_resolution.yaml: no 'resolution'"), std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "short.yaml") << "image: short.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
  std::ofstream(dir / "short.pgm", std::ios::binary) << "P5\n4 4\n255\nabc";
  try {
    ReadOccupancyMap(dir / "short.yaml");
    FAIL() << "accepted a truncated image";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "short.pgm: truncated (the header says 4x4 pixels, the file has 14 bytes)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace littermap::reconstruct
