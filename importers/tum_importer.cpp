#include "importers/tum_importer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <opencv2/core.hpp>

#include "bag/image_codec.hpp"
#include "bag/message_header.hpp"
#include "bag/output_guard.hpp"
#include "bag/png_decoder.hpp"
#include "bag/topics.hpp"
#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "importers/tum_sequence.hpp"

namespace littermap::importers {
namespace {

constexpr TimestampNs kMaxStampNs = 2'000'000'000LL * kNanosecondsPerSecond;  // int32 seconds

std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw BadInputError(path.string() + ": cannot open file");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(stream)),
                                  std::istreambuf_iterator<char>());
  if (stream.bad()) throw BadInputError(path.string() + ": read error");
  return bytes;
}

std::uint32_t BigEndian32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  return (std::uint32_t{bytes[offset]} << 24) | (std::uint32_t{bytes[offset + 1]} << 16) |
         (std::uint32_t{bytes[offset + 2]} << 8) | std::uint32_t{bytes[offset + 3]};
}

// The colour file as it is: PNG (the TUM format) or JPEG, recognised by their signatures. A PNG's
// size is read from its IHDR chunk (PNG spec 11.2.2) without decoding it.
msg::CompressedImage ColourMessage(const std::filesystem::path& path, const msg::Header& header,
                                   const msg::CameraInfo& camera) {
  msg::CompressedImage image;
  image.header = header;
  image.data = ReadFileBytes(path);
  const auto& d = image.data;
  static constexpr std::uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (d.size() >= 24 && std::equal(std::begin(kPng), std::end(kPng), d.begin())) {
    const std::uint32_t width = BigEndian32(d, 16);
    const std::uint32_t height = BigEndian32(d, 20);
    if (width != camera.width || height != camera.height) {
      throw BadInputError(path.string() + ": colour image is " + std::to_string(width) + "x" +
                          std::to_string(height) + ", the TUM calibration is for " +
                          std::to_string(camera.width) + "x" + std::to_string(camera.height));
    }
    image.format = "bgr8; png compressed bgr8";
  } else if (d.size() >= 3 && d[0] == 0xff && d[1] == 0xd8 && d[2] == 0xff) {
    image.format = "bgr8; jpeg compressed bgr8";
  } else {
    throw BadInputError(path.string() + ": colour image is neither PNG nor JPEG");
  }
  // Decoded once here, so that a damaged frame is refused at the door, not found by a later
  // command (about 5 ms a 640x480 frame).
  try {
    bag::DecodeColor(image);
  } catch (const BadInputError& error) {
    throw BadInputError(path.string() + ": colour " + error.what());
  }
  return image;
}

msg::CompressedImage DepthMessage(const std::filesystem::path& path, const msg::Header& header,
                                  const msg::CameraInfo& camera, const TumImportOptions& options) {
  const std::vector<std::uint8_t> bytes = ReadFileBytes(path);
  cv::Mat raw;
  try {
    raw = bag::DecodePng16(bytes);
  } catch (const BadInputError& error) {
    throw BadInputError(path.string() + ": depth image: " + error.what());
  }
  if (raw.cols != static_cast<int>(camera.width) || raw.rows != static_cast<int>(camera.height)) {
    throw BadInputError(path.string() + ": depth image is " + std::to_string(raw.cols) + "x" +
                        std::to_string(raw.rows) + ", the TUM calibration is for " +
                        std::to_string(camera.width) + "x" + std::to_string(camera.height));
  }
  return bag::EncodeDepthPng(TumDepthToMillimetres(raw, options.depth_units_per_m, path.string()),
                             header, options.codec);
}

TumCamera ChooseCamera(const std::filesystem::path& directory, const TumImportOptions& options,
                       TumImportResult& result) {
  if (options.camera) return *options.camera;
  const std::optional<TumCamera> camera = TumCameraFromDirectory(directory);
  if (!camera) {
    throw UsageError("cannot tell the TUM camera from the directory name '" + directory.string() +
                     "' (it names none of freiburg1/2/3, or several); choose it with "
                     "--camera fr1|fr2|fr3");
  }
  result.camera_from_directory = true;
  return *camera;
}

struct Sequence {
  std::vector<TumFrameEntry> colour;
  std::vector<TumFrameEntry> depth;
  std::vector<TumFramePair> pairs;
};

Sequence LoadSequence(const std::filesystem::path& directory, const TumImportOptions& options) {
  Sequence sequence;
  sequence.colour = ReadTumFrameList(directory / "rgb.txt");
  sequence.depth = ReadTumFrameList(directory / "depth.txt");
  sequence.pairs =
      AssociateTumFrames(sequence.colour, sequence.depth, options.max_association_gap_s);
  if (sequence.pairs.empty()) {
    throw BadInputError(directory.string() + ": no colour frame of rgb.txt has a depth frame of " +
                        "depth.txt within " + std::to_string(options.max_association_gap_s) + " s");
  }
  for (const TumFramePair& pair : sequence.pairs) {
    const TumFrameEntry& colour = sequence.colour[pair.colour_index];
    if (colour.stamp_ns < 0 || colour.stamp_ns > kMaxStampNs) {
      throw BadInputError((directory / "rgb.txt").string() + ": time stamp " +
                          bag::FormatTumStamp(colour.stamp_ns) + " is outside 0 .. 2e9 s");
    }
    const std::filesystem::path* files[] = {&colour.file, &sequence.depth[pair.depth_index].file};
    for (const std::filesystem::path* file : files) {
      if (!std::filesystem::is_regular_file(directory / *file)) {
        throw BadInputError((directory / *file).string() + ": listed but missing");
      }
    }
  }
  return sequence;
}

void WriteTumBag(const std::filesystem::path& directory, const std::filesystem::path& bag_path,
                 const Sequence& sequence, TumCamera camera, const TumImportOptions& options,
                 const ProgressCallback& progress) {
  bag::BagWriter writer(bag_path, options.bag);
  writer.AddTopic<msg::CameraInfo>(topics::kCameraInfo, bag::TopicQos::kSensorData);
  writer.AddTopic<msg::CompressedImage>(topics::kColor, bag::TopicQos::kSensorData);
  writer.AddTopic<msg::CompressedImage>(topics::kDepth, bag::TopicQos::kSensorData);
  const std::string task = "importing " + directory.filename().string();
  const std::size_t count = sequence.pairs.size();
  for (std::size_t i = 0; i < count; ++i) {
    const TumFrameEntry& colour = sequence.colour[sequence.pairs[i].colour_index];
    const TumFrameEntry& depth = sequence.depth[sequence.pairs[i].depth_index];
    const msg::Header header = bag::MakeHeader(colour.stamp_ns, frames::kCamera);
    const msg::CameraInfo info = TumCameraInfo(camera, header);
    writer.WriteMessage(topics::kCameraInfo, colour.stamp_ns, info);
    writer.WriteMessage(topics::kColor, colour.stamp_ns,
                        ColourMessage(directory / colour.file, header, info));
    writer.WriteMessage(topics::kDepth, colour.stamp_ns,
                        DepthMessage(directory / depth.file, header, info, options));
    ReportProgress(progress, {task, i + 1, count});
  }
  writer.Close();
}

}  // namespace

cv::Mat TumDepthToMillimetres(const cv::Mat& depth, double units_per_m, const std::string& source) {
  if (depth.type() != CV_16UC1) {
    throw BadInputError(source + ": depth image is not 16-bit single-channel");
  }
  if (!(units_per_m > 0)) throw UsageError("depth units per metre must be positive");
  cv::Mat millimetres(depth.size(), CV_16UC1);
  for (int row = 0; row < depth.rows; ++row) {
    const auto* in = depth.ptr<std::uint16_t>(row);
    auto* out = millimetres.ptr<std::uint16_t>(row);
    for (int col = 0; col < depth.cols; ++col) {
      // v * 1000 is exact, so the division rounds once; v / 5 is never a tie.
      const double mm = std::round(static_cast<double>(in[col]) * 1000.0 / units_per_m);
      out[col] = static_cast<std::uint16_t>(std::min(mm, 65535.0));
    }
  }
  return millimetres;
}

TumImportResult ImportTumSequence(const std::filesystem::path& directory,
                                  const std::filesystem::path& bag_path,
                                  const TumImportOptions& options,
                                  const ProgressCallback& progress) {
  if (!std::filesystem::is_directory(directory)) {
    throw BadInputError(directory.string() + ": not a directory");
  }
  TumImportResult result;
  result.camera = ChooseCamera(directory, options, result);
  const Sequence sequence = LoadSequence(directory, options);
  result.colour_listed = sequence.colour.size();
  result.depth_listed = sequence.depth.size();
  result.colour_without_depth = sequence.colour.size() - sequence.pairs.size();
  if (result.colour_without_depth > 0) {
    result.warnings.push_back(std::to_string(result.colour_without_depth) + " of " +
                              std::to_string(sequence.colour.size()) +
                              " colour frames have no depth frame within " +
                              std::to_string(options.max_association_gap_s) + " s; skipped");
  }
  bag::OutputGuard guard;  // the reference first: a bad path fails before the bag is written
  guard.Add(options.reference_path);
  guard.Add(bag_path);
  if (!options.reference_path.empty()) {
    const std::filesystem::path truth_path = directory / "groundtruth.txt";
    if (!std::filesystem::is_regular_file(truth_path)) {
      throw BadInputError(truth_path.string() + ": missing (a reference needs the ground truth)");
    }
    const std::vector<StampedPose> truth = bag::ReadTumTrajectory(truth_path);
    bag::WriteTumTrajectory(options.reference_path, truth);
    result.reference_poses = truth.size();
  }
  WriteTumBag(directory, bag_path, sequence, result.camera, options, progress);
  guard.Commit();
  result.pairs_written = sequence.pairs.size();
  result.duration_s = ToSeconds(sequence.colour[sequence.pairs.back().colour_index].stamp_ns -
                                sequence.colour[sequence.pairs.front().colour_index].stamp_ns);
  return result;
}

}  // namespace littermap::importers
