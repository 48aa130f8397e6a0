// `littermap simulate`: the sample world gives a bag with the run topics and the truth files.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "reconstruct/occupancy_map_file.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::RunLittermap;

using test::Quote;

int CountLines(const std::filesystem::path& path) {
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(SimulateCli, SampleWorldGivesBagAndTruth) {
  test::TempDir dir;
  const auto result =
      RunLittermap("simulate " + Quote(test::SampleWorld()) + " -o " + Quote(dir / "bag") +
                   " --truth " + Quote(dir / "truth") + " --duration 2 --seed 5");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(
      result.output.find("21 scans (urg-04lx), 101 odometry, 101 imu, 20 rgb-d frames, 2.0 s"),
      std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("(seed 5,"), std::string::npos) << result.output;

  const auto info = RunLittermap("info --json " + Quote(dir / "bag"));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  std::map<std::string, std::pair<std::string, int>> topics;
  const auto json = nlohmann::json::parse(info.output);
  for (const auto& topic : json.at("topics")) {
    topics[topic.at("name").get<std::string>()] = {topic.at("type").get<std::string>(),
                                                   topic.at("message_count").get<int>()};
  }
  EXPECT_EQ(topics["/scan"], std::make_pair(std::string("sensor_msgs/msg/LaserScan"), 21));
  EXPECT_EQ(topics["/odom"], std::make_pair(std::string("nav_msgs/msg/Odometry"), 101));
  EXPECT_EQ(topics["/imu"], std::make_pair(std::string("sensor_msgs/msg/Imu"), 101));
  EXPECT_EQ(topics["/tf_static"], std::make_pair(std::string("tf2_msgs/msg/TFMessage"), 1));
  const std::string image = "sensor_msgs/msg/CompressedImage";
  const std::string camera_info = "sensor_msgs/msg/CameraInfo";
  EXPECT_EQ(topics["/camera/color/image_raw/compressed"], std::make_pair(image, 20));
  EXPECT_EQ(topics["/camera/depth/image_raw/compressed"], std::make_pair(image, 20));
  EXPECT_EQ(topics["/camera/color/camera_info"], std::make_pair(camera_info, 20));
  EXPECT_EQ(topics["/camera/depth/camera_info"], std::make_pair(camera_info, 20));

  EXPECT_EQ(CountLines(dir / "truth" / "trajectory.tum"), 1 + 101);
  EXPECT_EQ(CountLines(dir / "truth" / "litter.csv"), 1 + 60);
  EXPECT_EQ(CountLines(dir / "truth" / "natural.csv"), 1 + 80);
  std::ifstream world_file(dir / "truth" / "world.json");
  const auto world = nlohmann::json::parse(world_file);
  EXPECT_EQ(world.at("seed"), 5);
  EXPECT_GT(world.at("objects").size(), 140u);
  EXPECT_EQ(CountLines(dir / "truth" / "masks" / "index.csv"), 1 + 2);  // frames 0 and 10
  EXPECT_TRUE(std::filesystem::exists(dir / "truth" / "masks" / "frame_000010.png"));
}

// `capture` with simulator sources is `simulate`: the same bag for the same world and seed.
TEST(SimulateCli, AnotherRouteAndRunSeedOfTheSamePark) {
  test::TempDir dir;
  const std::filesystem::path large =
      std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / "park_large.yaml";
  const auto run = [&](const std::string& name, const std::string& flags) {
    return RunLittermap("simulate " + Quote(large) + " -o " + Quote(dir / (name + "_bag")) +
                        " --truth " + Quote(dir / name) + " --duration 1 " + flags);
  };
  const auto lanes = run("lanes", "");
  ASSERT_EQ(lanes.exit_code, 0) << lanes.output;
  const auto perimeter = run("perimeter", "--route perimeter --run-seed 7");
  ASSERT_EQ(perimeter.exit_code, 0) << perimeter.output;
  EXPECT_NE(perimeter.output.find("(seed 11, run seed 7, route perimeter,"), std::string::npos)
      << perimeter.output;
  const auto world = [&](const std::string& name) {
    return nlohmann::json::parse(std::ifstream(dir / name / "world.json"));
  };
  EXPECT_EQ(world("lanes").at("objects"), world("perimeter").at("objects"));  // one park
  EXPECT_NE(world("lanes").at("route_m"), world("perimeter").at("route_m"));
  EXPECT_EQ(world("perimeter").at("route"), "perimeter");
  EXPECT_EQ(world("perimeter").at("run_seed"), 7);

  const auto unknown = run("unknown", "--route lawn");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("no route named 'lawn' (routes: route, perimeter, diagonals)"),
            std::string::npos)
      << unknown.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "unknown_bag"));
}

// TRUTH_DIR/map.yaml: the run's scans at the true poses. Its occupied cells lie on the world's
// structure (trunks, rocks, benches, bins, fences, bushes), not on the ground.
TEST(SimulateCli, TruthMapShowsTheWorldsStructure) {
  test::TempDir dir;
  const auto result =
      RunLittermap("-q simulate " + Quote(test::SampleWorld()) + " -o " + Quote(dir / "bag") +
                   " --truth " + Quote(dir / "truth") + " --duration 8");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const reconstruct::Points2 occupied =
      reconstruct::OccupiedCellCentres(reconstruct::ReadOccupancyMap(dir / "truth" / "map.yaml"));
  ASSERT_GT(occupied.size(), 50u);
  const auto world = nlohmann::json::parse(std::ifstream(dir / "truth" / "world.json"));
  std::vector<std::pair<Eigen::Vector2d, double>> footprints;  // centre, radius
  for (const auto& o : world.at("objects")) {
    const std::string kind = o.at("kind");
    if (kind == "litter" || kind == "natural") continue;
    const auto& c = o.at("center_m");
    const auto& size = o.at("size_m");
    footprints.push_back({{c[0].get<double>(), c[1].get<double>()},
                          0.5 * std::hypot(size[0].get<double>(), size[1].get<double>())});
  }
  std::size_t on_structure = 0;
  for (const Eigen::Vector2d& p : occupied) {
    for (const auto& [centre, radius] : footprints) {
      if ((p - centre).norm() <= radius + 0.15) {
        ++on_structure;
        break;
      }
    }
  }
  // Measured: 281 of 281; mixed pixels at trunk edges may land a little off.
  EXPECT_GE(static_cast<double>(on_structure), 0.97 * static_cast<double>(occupied.size()))
      << on_structure << " of " << occupied.size();
}

TEST(SimulateCli, CaptureFromSimSourcesIsSimulate) {
  test::TempDir dir;
  const std::string sim = "sim:" + test::SampleWorld().string();
  const auto result =
      RunLittermap("capture --camera '" + sim + "' --laser '" + sim + "' -o " + Quote(dir / "bag") +
                   " --duration 1 --seed 5 " + "--contact-sheet " + Quote(dir / "sheet.png"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("11 scans (urg-04lx), 51 odometry, 51 imu, 10 rgb-d frames"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "truth"));  // no --truth: the bag only
  // The contact sheet: 6 rows of three 320x240 panels.
  const auto info = RunLittermap("info --verify " + Quote(dir / "bag"));
  EXPECT_EQ(info.exit_code, 0) << info.output;
  std::ifstream png(dir / "sheet.png", std::ios::binary);
  std::string header(24, '\0');
  png.read(header.data(), 24);
  ASSERT_EQ(header.substr(1, 3), "PNG");
  const auto be32 = [&](int at) {
    return (std::uint8_t(header[at]) << 24) | (std::uint8_t(header[at + 1]) << 16) |
           (std::uint8_t(header[at + 2]) << 8) | std::uint8_t(header[at + 3]);
  };
  EXPECT_EQ(be32(16), 960);
  EXPECT_EQ(be32(20), 6 * 240);
}

TEST(SimulateCli, CaptureRefusesMixingSimulatedAndRealSensors) {
  test::TempDir dir;
  const std::string sim = "sim:" + test::SampleWorld().string();
  const auto real =
      RunLittermap("capture --camera openni2:// --laser '" + sim + "' -o " + Quote(dir / "bag"));
  EXPECT_EQ(real.exit_code, 1) << real.output;
  EXPECT_NE(real.output.find("--camera 'openni2://': a simulated capture needs --camera "
                             "sim:WORLD.yaml as well"),
            std::string::npos)
      << real.output;
  const auto laser =
      RunLittermap("capture --camera '" + sim + "' --laser /dev/ttyACM0 -o " + Quote(dir / "bag"));
  EXPECT_EQ(laser.exit_code, 1) << laser.output;
  EXPECT_NE(laser.output.find("--laser '/dev/ttyACM0'"), std::string::npos) << laser.output;
  const auto mixed = RunLittermap("capture --camera '" + sim + "' --laser sim:other.yaml -o " +
                                  Quote(dir / "bag"));
  EXPECT_EQ(mixed.exit_code, 1) << mixed.output;
  EXPECT_NE(mixed.output.find("must simulate the same world"), std::string::npos) << mixed.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

TEST(SimulateCli, BadWorldExitsTwoNamingFileAndKey) {
  test::TempDir dir;
  std::ofstream(dir / "w.yaml") << "route: {waypoints_m: [[0, 0], [5, 0]]}\nlitter: {cont: 3}\n";
  const auto result = RunLittermap("simulate " + Quote(dir / "w.yaml") + " -o " +
                                   Quote(dir / "bag") + " --truth " + Quote(dir / "t"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("w.yaml: litter.cont: unknown key"), std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
  EXPECT_EQ(RunLittermap("simulate " + Quote(test::SampleWorld()) + " -o x").exit_code,
            1);  // no --truth
  // Numbers from the command line are checked where they are read, not wrapped or run on.
  for (const char* flags : {"--seed -1", "--run-seed -2", "--litter-day 1000000000"}) {
    const auto refused =
        RunLittermap("simulate " + Quote(test::SampleWorld()) + " -o " + Quote(dir / "bag") +
                     " --truth " + Quote(dir / "t") + " " + flags);
    EXPECT_EQ(refused.exit_code, 1) << flags << ": " << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "bag")) << flags;
  }
}

}  // namespace
}  // namespace littermap
