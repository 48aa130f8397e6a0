// `littermap simulate`: the sample world gives a bag with the run topics and the truth files.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using testing::RunLittermap;

const std::filesystem::path kWorld =
    std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / "park_small.yaml";

std::string Quote(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

int CountLines(const std::filesystem::path& path) {
  std::ifstream in(path);
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

TEST(SimulateCli, SampleWorldGivesBagAndTruth) {
  testing::TempDir dir;
  const auto result = RunLittermap("simulate " + Quote(kWorld) + " -o " + Quote(dir / "bag") +
                                   " --truth " + Quote(dir / "truth") + " --duration 4 --seed 5");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("41 scans (urg-04lx), 201 odometry, 201 imu, 4.0 s"),
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
  EXPECT_EQ(topics["/scan"], std::make_pair(std::string("sensor_msgs/msg/LaserScan"), 41));
  EXPECT_EQ(topics["/odom"], std::make_pair(std::string("nav_msgs/msg/Odometry"), 201));
  EXPECT_EQ(topics["/imu"], std::make_pair(std::string("sensor_msgs/msg/Imu"), 201));
  EXPECT_EQ(topics["/tf_static"], std::make_pair(std::string("tf2_msgs/msg/TFMessage"), 1));

  EXPECT_EQ(CountLines(dir / "truth" / "trajectory.tum"), 1 + 201);
  EXPECT_EQ(CountLines(dir / "truth" / "litter.csv"), 1 + 60);
  EXPECT_EQ(CountLines(dir / "truth" / "natural.csv"), 1 + 80);
  std::ifstream world_file(dir / "truth" / "world.json");
  const auto world = nlohmann::json::parse(world_file);
  EXPECT_EQ(world.at("seed"), 5);
  EXPECT_GT(world.at("objects").size(), 140u);
}

TEST(SimulateCli, BadWorldExitsTwoNamingFileAndKey) {
  testing::TempDir dir;
  std::ofstream(dir / "w.yaml") << "route: {waypoints_m: [[0, 0], [5, 0]]}\nlitter: {cont: 3}\n";
  const auto result = RunLittermap("simulate " + Quote(dir / "w.yaml") + " -o " +
                                   Quote(dir / "bag") + " --truth " + Quote(dir / "t"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("w.yaml: litter.cont: unknown key"), std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
  EXPECT_EQ(RunLittermap("simulate " + Quote(kWorld) + " -o x").exit_code, 1);  // no --truth
}

}  // namespace
}  // namespace littermap
