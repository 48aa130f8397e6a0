// Bags as real ROS 2 robots record them survey like littermap's own: the same simulated run in
// MCAP storage, and rewritten the way a robot publishes it (sensors on other topics, raw colour
// and float depth images, mountings on /tf beside the moving odom -> base_link), give the same
// trajectory and the same litter items, byte for byte, with no option to name a topic.

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "bag/image_codec.hpp"
#include "bag/message_stream.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;

using test::Slurp;

msg::Image RawColour(const msg::CompressedImage& jpeg) {
  const cv::Mat bgr = bag::DecodeColor(jpeg);
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  msg::Image image;
  image.header = jpeg.header;
  image.height = static_cast<std::uint32_t>(rgb.rows);
  image.width = static_cast<std::uint32_t>(rgb.cols);
  image.encoding = "rgb8";
  image.step = image.width * 3 + 4;  // padded rows, as some drivers send them
  image.data.assign(std::size_t{image.step} * image.height, 0);
  for (int v = 0; v < rgb.rows; ++v) {
    std::memcpy(image.data.data() + std::size_t{image.step} * v, rgb.ptr(v), image.width * 3);
  }
  return image;
}

msg::Image FloatDepth(const msg::CompressedImage& png) {
  const cv::Mat mm = bag::DecodeDepthMm(png);
  msg::Image image;
  image.header = png.header;
  image.height = static_cast<std::uint32_t>(mm.rows);
  image.width = static_cast<std::uint32_t>(mm.cols);
  image.encoding = "32FC1";
  image.step = image.width * 4;
  image.data.resize(std::size_t{image.step} * image.height);
  auto* metres = reinterpret_cast<float*>(image.data.data());
  for (int v = 0; v < mm.rows; ++v) {
    for (int u = 0; u < mm.cols; ++u) {
      const std::uint16_t d = mm.at<std::uint16_t>(v, u);
      metres[v * mm.cols + u] =
          d == 0 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(d) / 1000.0f;
    }
  }
  return image;
}

// The run as a robot with its own topic names records it, in MCAP.
void RewriteAsRobot(const std::filesystem::path& from, const std::filesystem::path& to) {
  bag::BagReader reader(from);
  bag::MessageStream stream(reader);
  bag::BagWriterOptions options;
  options.storage = "mcap";
  bag::BagWriter writer(to, options);
  writer.AddTopic<msg::LaserScan>("/scan_front");
  writer.AddTopic<msg::Odometry>("/odometry/filtered");
  writer.AddTopic<msg::Imu>("/imu_data");
  writer.AddTopic<msg::TFMessage>("/tf");
  writer.AddTopic<msg::CameraInfo>("/camera/camera/color/camera_info");
  writer.AddTopic<msg::Image>("/camera/camera/color/image_raw");
  writer.AddTopic<msg::Image>("/camera/camera/aligned_depth_to_color/image_raw");
  msg::TFMessage mounts;
  while (auto m = stream.Next()) {
    const std::string& topic = m->topic->name;
    const TimestampNs t = m->timestamp_ns;
    if (const auto* tf_static = std::get_if<msg::TFMessage>(&m->message)) {
      mounts = *tf_static;
    } else if (const auto* scan = std::get_if<msg::LaserScan>(&m->message)) {
      writer.WriteMessage("/scan_front", t, *scan);
    } else if (const auto* odom = std::get_if<msg::Odometry>(&m->message)) {
      writer.WriteMessage("/odometry/filtered", t, *odom);
      // A robot's /tf: the moving odom -> base_link, and the mountings again and again.
      msg::TFMessage tf = mounts;
      msg::TransformStamped moving;
      moving.header = odom->header;
      moving.child_frame_id = "base_link";
      moving.transform.translation.x = odom->pose.pose.position.x;
      moving.transform.translation.y = odom->pose.pose.position.y;
      moving.transform.rotation = odom->pose.pose.orientation;
      tf.transforms.push_back(moving);
      writer.WriteMessage("/tf", t, tf);
    } else if (const auto* imu = std::get_if<msg::Imu>(&m->message)) {
      writer.WriteMessage("/imu_data", t, *imu);
    } else if (const auto* info = std::get_if<msg::CameraInfo>(&m->message)) {
      if (topic.find("depth") == std::string::npos) {
        writer.WriteMessage("/camera/camera/color/camera_info", t, *info);
      }
    } else if (const auto* image = std::get_if<msg::CompressedImage>(&m->message)) {
      if (topic.find("depth") == std::string::npos) {
        writer.WriteMessage("/camera/camera/color/image_raw", t, RawColour(*image));
      } else {
        writer.WriteMessage("/camera/camera/aligned_depth_to_color/image_raw", t,
                            FloatDepth(*image));
      }
    }
  }
  writer.Close();
}

void Survey(const std::filesystem::path& bag, const std::filesystem::path& out) {
  const auto result =
      RunLittermap("-q survey " + Quote(bag) + " --site " + Quote(out.string() + ".gpkg") + " -o " +
                   Quote(out) + " --every 3");
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

TEST(RobotBagSurveyCli, McapAndARobotsTopicsGiveTheSameResults) {
  test::TempDir dir;
  const auto world = std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples/worlds/park_small.yaml";
  for (const std::string storage : {"sqlite3", "mcap"}) {
    const auto result = RunLittermap(
        "-q simulate " + Quote(world) + " -o " + Quote(dir / ("bag-" + storage)) + " --truth " +
        Quote(dir / ("truth-" + storage)) + " --duration 30 --storage " + storage);
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
  RewriteAsRobot(dir / "bag-sqlite3", dir / "bag-robot");
  const auto info = RunLittermap("info " + Quote(dir / "bag-robot"));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("Storage id:        mcap"), std::string::npos) << info.output;
  // Which topic each sensor role is read from, before any command needs it.
  for (const char* role : {"scan: /scan_front (by type)", "odometry: /odometry/filtered (by type)",
                           "imu: /imu_data (by type)", "colour: /camera/camera/color/image_raw",
                           "depth: /camera/camera/aligned_depth_to_color/image_raw",
                           "camera_info: /camera/camera/color/camera_info"}) {
    EXPECT_NE(info.output.find(role), std::string::npos) << role << "\n" << info.output;
  }

  for (const std::string run : {"sqlite3", "mcap", "robot"}) {
    ASSERT_NO_FATAL_FAILURE(Survey(dir / ("bag-" + run), dir / ("out-" + run)));
  }
  const std::string items = Slurp(dir / "out-sqlite3/run/items.csv");
  const std::string trajectory = Slurp(dir / "out-sqlite3/run/trajectory.tum");
  ASSERT_GT(std::count(items.begin(), items.end(), '\n'), 1) << "no litter found in 30 s";
  for (const std::string run : {"mcap", "robot"}) {
    SCOPED_TRACE(run);
    EXPECT_EQ(Slurp(dir / ("out-" + run) / "run/items.csv"), items);
    EXPECT_EQ(Slurp(dir / ("out-" + run) / "run/trajectory.tum"), trajectory);
  }
}

}  // namespace
}  // namespace littermap
