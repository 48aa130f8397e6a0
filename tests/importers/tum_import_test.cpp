// TUM RGB-D import: a tiny sequence built from the real frame pair of shared/datasets/tum_pair
// (freiburg2 desk), read back from the bag.

#include "importers/tum_importer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <opencv2/imgcodecs.hpp>

#include "bag/bag_reader.hpp"
#include "bag/topics.hpp"
#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "importers/tum_sequence.hpp"
#include "support/temp_dir.hpp"

namespace littermap::importers {
namespace {

const std::filesystem::path kPairDir = std::filesystem::path(LITTERMAP_DATASETS_DIR) / "tum_pair";

std::vector<std::uint8_t> FileBytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

// DIR/rgb/{1,2}.png, DIR/depth/{1,2}.png, rgb.txt with a third colour frame that has no depth
// partner within 0.02 s, depth.txt, groundtruth.txt.
void BuildSequence(const std::filesystem::path& dir) {
  for (const char* file : {"1.png", "2.png", "1_depth.png", "2_depth.png"}) {
    ASSERT_TRUE(std::filesystem::exists(kPairDir / file)) << "missing data set " << kPairDir;
  }
  std::filesystem::create_directories(dir / "rgb");
  std::filesystem::create_directories(dir / "depth");
  std::filesystem::copy_file(kPairDir / "1.png", dir / "rgb" / "1.png");
  std::filesystem::copy_file(kPairDir / "2.png", dir / "rgb" / "2.png");
  std::filesystem::copy_file(kPairDir / "1_depth.png", dir / "depth" / "1.png");
  std::filesystem::copy_file(kPairDir / "2_depth.png", dir / "depth" / "2.png");
  std::ofstream(dir / "rgb.txt") << "# color images\n# timestamp filename\n"
                                    "1311868164.363181 rgb/1.png\n1311868164.399026 rgb/2.png\n"
                                    "1311868170.000000 rgb/1.png\n";
  std::ofstream(dir / "depth.txt") << "# depth maps\n1311868164.373557 depth/1.png\n"
                                      "1311868164.407784 depth/2.png\n";
  std::ofstream(dir / "groundtruth.txt")
      << "# ground truth trajectory\n"
         "1311868164.3646 -0.1346 -0.8521 1.4866 0.6513 0.6485 -0.2785 -0.2801\n"
         "1311868164.3746 -0.1345 -0.8524 1.4864 0.6514 0.6485 -0.2782 -0.2801\n";
}

struct Frames {
  std::vector<msg::CameraInfo> infos;
  std::vector<msg::CompressedImage> colour;
  std::vector<msg::CompressedImage> depth;
  std::vector<TimestampNs> times;
};

Frames ReadFrames(const std::filesystem::path& bag) {
  Frames frames;
  bag::BagReader reader(bag);
  while (auto message = reader.Next()) {
    const std::string& topic = message->topic->name;
    if (topic == topics::kCameraInfo) {
      frames.infos.push_back(bag::Decode<msg::CameraInfo>(message->data));
      frames.times.push_back(message->timestamp_ns);
    } else if (topic == topics::kColor) {
      frames.colour.push_back(bag::Decode<msg::CompressedImage>(message->data));
    } else if (topic == topics::kDepth) {
      frames.depth.push_back(bag::Decode<msg::CompressedImage>(message->data));
    }
  }
  return frames;
}

TEST(TumImport, TinySequenceReadsBackWithDepthInMillimetres) {
  test::TempDir temp;
  const auto sequence = temp / "rgbd_dataset_freiburg2_tiny";
  BuildSequence(sequence);
  TumImportOptions options;
  options.reference_path = temp / "ref.tum";
  const TumImportResult result = ImportTumSequence(sequence, temp / "bag", options);
  EXPECT_EQ(result.camera, TumCamera::kFreiburg2);
  EXPECT_TRUE(result.camera_from_directory);
  EXPECT_EQ(result.colour_listed, 3u);
  EXPECT_EQ(result.pairs_written, 2u);
  EXPECT_EQ(result.colour_without_depth, 1u);
  EXPECT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.reference_poses, 2u);

  const Frames frames = ReadFrames(temp / "bag");
  ASSERT_EQ(frames.infos.size(), 2u);
  ASSERT_EQ(frames.colour.size(), 2u);
  ASSERT_EQ(frames.depth.size(), 2u);
  EXPECT_EQ(frames.times[0], 1'311'868'164'363'181'000);
  for (int i = 0; i < 2; ++i) {
    SCOPED_TRACE(i);
    const std::string n = std::to_string(i + 1);
    // Colour: the PNG file's bytes unchanged, decodable as BGR.
    EXPECT_EQ(frames.colour[i].format, "bgr8; png compressed bgr8");
    EXPECT_EQ(frames.colour[i].data, FileBytes(kPairDir / (n + ".png")));
    const cv::Mat colour = bag::DecodeColor(frames.colour[i]);
    EXPECT_EQ(cv::norm(colour, cv::imread((kPairDir / (n + ".png")).string()), cv::NORM_INF), 0);
    // Depth: round(v / 5) of the raw TUM depth (5000 units per metre), 0 stays 0.
    const cv::Mat raw = cv::imread((kPairDir / (n + "_depth.png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(raw.type(), CV_16UC1);
    const cv::Mat depth_mm = bag::DecodeDepthMm(frames.depth[i]);
    ASSERT_EQ(depth_mm.size(), raw.size());
    int checked = 0;
    for (int row = 0; row < raw.rows; ++row) {
      for (int col = 0; col < raw.cols; ++col) {
        const int v = raw.at<std::uint16_t>(row, col);
        ASSERT_EQ(depth_mm.at<std::uint16_t>(row, col), (v + 2) / 5) << row << "," << col;
        checked += v > 0;
      }
    }
    EXPECT_GT(checked, 100000) << "the desk frame has plenty of depth readings";
    // The header of all three messages: the colour frame's time, the camera's optical frame.
    EXPECT_EQ(frames.depth[i].header, frames.colour[i].header);
    EXPECT_EQ(frames.infos[i].header, frames.colour[i].header);
    EXPECT_EQ(frames.colour[i].header.frame_id, frames::kCamera);
  }
  const msg::CameraInfo& info = frames.infos[0];
  EXPECT_EQ(info.width, 640u);
  EXPECT_EQ(info.height, 480u);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  ASSERT_EQ(info.d.size(), 5u);
  EXPECT_DOUBLE_EQ(info.d[0], 0.231222);
  // README: freiburg2, fx 520.909, fy 521.007, cx 325.141, cy 249.702.
  EXPECT_NEAR(info.k[0], 520.909, 1e-3);
  EXPECT_NEAR(info.k[4], 521.007, 1e-3);
  EXPECT_NEAR(info.k[2], 325.141, 1e-3);
  EXPECT_NEAR(info.k[5], 249.702, 1e-3);
  EXPECT_EQ(info.p[0], info.k[0]);
  EXPECT_EQ(info.k[8], 1.0);

  const std::vector<StampedPose> reference = bag::ReadTumTrajectory(temp / "ref.tum");
  ASSERT_EQ(reference.size(), 2u);
  EXPECT_EQ(reference[0].stamp_ns, 1'311'868'164'364'600'000);
}

TEST(TumImport, CameraMustBeKnown) {
  test::TempDir temp;
  BuildSequence(temp / "desk");
  EXPECT_THROW(ImportTumSequence(temp / "desk", temp / "bag"), UsageError);
  EXPECT_FALSE(std::filesystem::exists(temp / "bag"));
  TumImportOptions options;
  options.camera = TumCamera::kFreiburg3;
  const TumImportResult result = ImportTumSequence(temp / "desk", temp / "bag", options);
  EXPECT_EQ(result.camera, TumCamera::kFreiburg3);
  EXPECT_FALSE(result.camera_from_directory);
  EXPECT_EQ(ParseTumCamera("FR2"), TumCamera::kFreiburg2);
  EXPECT_EQ(ParseTumCamera("freiburg1"), TumCamera::kFreiburg1);
  EXPECT_EQ(ParseTumCamera("kinect"), std::nullopt);
  EXPECT_EQ(TumCameraFromDirectory("/data/rgbd_dataset_freiburg3_long_office/"),
            TumCamera::kFreiburg3);
  EXPECT_EQ(TumCameraFromDirectory("/data/freiburg1_vs_freiburg2"), std::nullopt);
}

TEST(TumImport, MissingImageIsBadInputNamingTheFile) {
  test::TempDir temp;
  const auto sequence = temp / "rgbd_dataset_freiburg2_tiny";
  BuildSequence(sequence);
  std::filesystem::remove(sequence / "depth" / "2.png");
  try {
    ImportTumSequence(sequence, temp / "bag");
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& error) {
    EXPECT_NE(std::string(error.what()).find("depth/2.png"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(temp / "bag"));
}

TEST(TumImport, MalformedListLineIsBadInputWithLine) {
  test::TempDir temp;
  const auto sequence = temp / "rgbd_dataset_freiburg2_tiny";
  BuildSequence(sequence);
  std::ofstream(sequence / "depth.txt") << "# depth\n1311868164.373557\n";
  try {
    ImportTumSequence(sequence, temp / "bag");
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& error) {
    EXPECT_NE(std::string(error.what()).find("depth.txt:2: field 'filename'"), std::string::npos)
        << error.what();
  }
}

TEST(TumImport, AssociationTakesClosestPairsOnce) {
  const auto at = [](double seconds) { return TumFrameEntry{FromSeconds(seconds), "x.png"}; };
  // Both colour frames are within 0.02 s of the single depth frame; the closer one wins.
  const auto pairs = AssociateTumFrames({at(1.000), at(1.012)}, {at(1.010)});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].colour_index, 1u);
  EXPECT_EQ(pairs[0].depth_index, 0u);
  EXPECT_TRUE(AssociateTumFrames({at(1.0)}, {at(1.03)}).empty());
}

TEST(TumImport, DepthConversionRoundsAndSaturates) {
  cv::Mat raw(1, 4, CV_16UC1);
  raw.at<std::uint16_t>(0, 0) = 0;
  raw.at<std::uint16_t>(0, 1) = 12;     // 2.4 mm -> 2
  raw.at<std::uint16_t>(0, 2) = 13;     // 2.6 mm -> 3
  raw.at<std::uint16_t>(0, 3) = 65535;  // 13107 mm
  const cv::Mat mm = TumDepthToMillimetres(raw, 5000, "test");
  EXPECT_EQ(mm.at<std::uint16_t>(0, 0), 0);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 1), 2);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 2), 3);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 3), 13107);
  EXPECT_EQ(TumDepthToMillimetres(raw, 100, "test").at<std::uint16_t>(0, 3), 65535);
  EXPECT_THROW(TumDepthToMillimetres(cv::Mat(2, 2, CV_8UC3), 5000, "x.png"), BadInputError);
}

}  // namespace
}  // namespace littermap::importers
