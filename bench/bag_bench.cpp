// Run-bag throughput: recording 640x480 colour (JPEG) + depth (16-bit PNG) at 30 Hz, a 1081-beam
// laser at 40 Hz and odometry at 50 Hz, encoding included, must run at least 3x faster than real
// time on one core. One benchmark iteration = one second of sensor data, so the iteration rate
// ("x_realtime") is the real-time factor. Reading reports MB/s and messages/s. Each benchmark
// runs on both storages: /0 sqlite3, /1 MCAP (zstd chunks), /2 MCAP (lz4 chunks).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "bag/image_codec.hpp"
#include "bag/message_stream.hpp"
#include "bag/topics.hpp"

namespace littermap {
namespace {

constexpr int kCameraHz = 30, kLaserHz = 40, kOdometryHz = 50;
constexpr int kLaserBeams = 1081;

// The real Kinect frames of the TUM freiburg2 pair (depth converted to millimetres), so encoding
// costs what it costs on real data; alternate frames are flipped so no two in a row are equal.
std::vector<cv::Mat> RealFrames(const char* name, int flags, double scale) {
  const std::string path = std::string(LITTERMAP_DATASETS_DIR) + "/tum_pair/" + name;
  cv::Mat image = cv::imread(path, flags);
  if (image.empty()) throw std::runtime_error("benchmark data missing: " + path);
  if (scale != 1.0) image.convertTo(image, image.type(), scale);
  cv::Mat flipped;
  cv::flip(image, flipped, 1);
  return {image, flipped};
}

std::vector<cv::Mat> ColourFrames() {
  auto frames = RealFrames("1.png", cv::IMREAD_COLOR, 1.0);
  auto more = RealFrames("2.png", cv::IMREAD_COLOR, 1.0);
  frames.insert(frames.end(), more.begin(), more.end());
  return frames;
}

std::vector<cv::Mat> DepthFrames() {
  auto frames = RealFrames("1_depth.png", cv::IMREAD_UNCHANGED, 0.2);  // 5000/m -> mm
  auto more = RealFrames("2_depth.png", cv::IMREAD_UNCHANGED, 0.2);
  frames.insert(frames.end(), more.begin(), more.end());
  return frames;
}

msg::LaserScan Scan(TimestampNs t, std::mt19937& random) {
  std::uniform_real_distribution<float> range(0.5f, 30.f);
  msg::LaserScan scan;
  scan.header.stamp = {static_cast<std::int32_t>(t / kNanosecondsPerSecond),
                       static_cast<std::uint32_t>(t % kNanosecondsPerSecond)};
  scan.header.frame_id = frames::kLaser;
  scan.angle_min = -2.356f;
  scan.angle_increment = 0.004363f;
  scan.angle_max = scan.angle_min + scan.angle_increment * (kLaserBeams - 1);
  scan.range_max = 30.f;
  scan.ranges.resize(kLaserBeams);
  scan.intensities.resize(kLaserBeams);
  for (int i = 0; i < kLaserBeams; ++i) {
    scan.ranges[static_cast<std::size_t>(i)] = range(random);
    scan.intensities[static_cast<std::size_t>(i)] = 1000.f;
  }
  return scan;
}

struct Recorder {
  std::vector<cv::Mat> colour = ColourFrames();
  std::vector<cv::Mat> depth = DepthFrames();
  std::mt19937 random{3};
  std::int64_t second = 0;

  void RecordOneSecond(bag::BagWriter& writer) {
    const TimestampNs base = (1'700'000'000 + second++) * kNanosecondsPerSecond;
    for (int i = 0; i < kCameraHz; ++i) {
      const TimestampNs t = base + i * kNanosecondsPerSecond / kCameraHz;
      msg::Header header{{static_cast<std::int32_t>(t / kNanosecondsPerSecond), 0},
                         frames::kCamera};
      const auto frame = static_cast<std::size_t>(i) % colour.size();
      writer.WriteMessage(topics::kColor, t, bag::EncodeColorJpeg(colour[frame], header));
      writer.WriteMessage(topics::kDepth, t, bag::EncodeDepthPng(depth[frame], header));
    }
    for (int i = 0; i < kLaserHz; ++i) {
      const TimestampNs t = base + i * kNanosecondsPerSecond / kLaserHz;
      writer.WriteMessage(topics::kScan, t, Scan(t, random));
    }
    for (int i = 0; i < kOdometryHz; ++i) {
      const TimestampNs t = base + i * kNanosecondsPerSecond / kOdometryHz;
      msg::Odometry odometry;
      odometry.header.frame_id = frames::kOdom;
      odometry.child_frame_id = frames::kBase;
      odometry.pose.pose.position.x = static_cast<double>(i);
      writer.WriteMessage(topics::kOdometry, t, odometry);
    }
  }
};

void BM_EncodeColourJpeg(benchmark::State& state) {
  const auto frames = ColourFrames();
  std::size_t i = 0, bytes = 0;
  for (auto _ : state) bytes += bag::EncodeColorJpeg(frames[i++ % frames.size()], {}).data.size();
  state.counters["KB/frame"] = static_cast<double>(bytes) / 1e3 / static_cast<double>(i);
}
BENCHMARK(BM_EncodeColourJpeg)->Unit(benchmark::kMillisecond);

void BM_EncodeDepthPng(benchmark::State& state) {
  const auto frames = DepthFrames();
  std::size_t i = 0, bytes = 0;
  for (auto _ : state) bytes += bag::EncodeDepthPng(frames[i++ % frames.size()], {}).data.size();
  state.counters["KB/frame"] = static_cast<double>(bytes) / 1e3 / static_cast<double>(i);
}
BENCHMARK(BM_EncodeDepthPng)->Unit(benchmark::kMillisecond);

void AddTopics(bag::BagWriter& writer) {
  writer.AddTopic<msg::CompressedImage>(topics::kColor);
  writer.AddTopic<msg::CompressedImage>(topics::kDepth);
  writer.AddTopic<msg::LaserScan>(topics::kScan);
  writer.AddTopic<msg::Odometry>(topics::kOdometry);
}

bag::BagWriterOptions StorageOptions(const benchmark::State& state) {
  bag::BagWriterOptions options;
  options.storage = state.range(0) == 0 ? "sqlite3" : "mcap";
  options.mcap.compression =
      state.range(0) == 2 ? bag::McapCompression::kLz4 : bag::McapCompression::kZstd;
  return options;
}

void SetStorageLabel(benchmark::State& state) {
  const char* labels[] = {"sqlite3", "mcap zstd", "mcap lz4"};
  state.SetLabel(labels[state.range(0)]);
}

// MB/s and messages/s of a benchmark over the bag at `path`, which it then removes.
void ReportRates(benchmark::State& state, const std::filesystem::path& path, std::uint64_t bytes,
                 std::uint64_t messages) {
  state.counters["MB/s"] =
      benchmark::Counter(static_cast<double>(bytes) / 1e6, benchmark::Counter::kIsRate);
  state.counters["msgs/s"] =
      benchmark::Counter(static_cast<double>(messages), benchmark::Counter::kIsRate);
  SetStorageLabel(state);
  std::filesystem::remove_all(path);
}

std::filesystem::path BenchDir(const char* name) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(path);
  return path;
}

void BM_RecordOneSecondOfSensors(benchmark::State& state) {
  const auto path = BenchDir("littermap-bench-write");
  Recorder recorder;
  std::uint64_t messages = 0, bytes = 0;
  {
    bag::BagWriter writer(path, StorageOptions(state));
    AddTopics(writer);
    for (auto _ : state) {
      recorder.RecordOneSecond(writer);
    }
    writer.Close();
    messages = writer.message_count();
    bytes = writer.bytes_written();
  }
  state.counters["x_realtime"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  ReportRates(state, path, bytes, messages);
}
BENCHMARK(BM_RecordOneSecondOfSensors)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(5)
    ->DenseRange(0, 2);

// 10 s of recording in the storage the benchmark's argument names.
std::filesystem::path TenSecondBag(const benchmark::State& state, const char* name) {
  const auto path = BenchDir(name);
  bag::BagWriter writer(path, StorageOptions(state));
  AddTopics(writer);
  Recorder recorder;
  for (int second = 0; second < 10; ++second) recorder.RecordOneSecond(writer);
  return path;
}

std::uint64_t StorageBytes(const bag::BagReader& reader) {
  std::uint64_t bytes = 0;
  for (const auto& file : reader.info().files) {
    bytes += std::filesystem::file_size(reader.directory() / file.relative_path);
  }
  return bytes;
}

// Reads back 10 s of recording, messages as stored (no decoding): the storage alone.
void BM_ReadRaw(benchmark::State& state) {
  const auto path = TenSecondBag(state, "littermap-bench-read-raw");
  std::uint64_t messages = 0, bytes = 0;
  for (auto _ : state) {
    bag::BagReader reader(path);
    while (auto message = reader.Next()) {
      benchmark::DoNotOptimize(message->data.data());
      ++messages;
    }
    bytes += StorageBytes(reader);
  }
  ReportRates(state, path, bytes, messages);
}
BENCHMARK(BM_ReadRaw)->Unit(benchmark::kMillisecond)->UseRealTime()->DenseRange(0, 2);

// Reads back and CDR-decodes 10 s of recording (images stay compressed, as a stage that only
// needs some frames would leave them).
void BM_ReadAndDecode(benchmark::State& state) {
  const auto path = TenSecondBag(state, "littermap-bench-read");
  std::uint64_t messages = 0, bytes = 0;
  for (auto _ : state) {
    bag::BagReader reader(path);
    bag::MessageStream stream(reader);
    while (auto message = stream.Next()) {
      benchmark::DoNotOptimize(message->message);
      ++messages;
    }
    bytes += StorageBytes(reader);
  }
  ReportRates(state, path, bytes, messages);
}
BENCHMARK(BM_ReadAndDecode)->Unit(benchmark::kMillisecond)->UseRealTime()->DenseRange(0, 2);

}  // namespace
}  // namespace littermap

BENCHMARK_MAIN();
