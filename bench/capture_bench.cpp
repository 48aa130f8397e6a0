// Sustained recording: the recorder (capture/recorder.hpp) fed at the robot's real rates — a
// 640x480 RGB-D camera at 30 Hz (real TUM freiburg2 images, so JPEG and PNG work as hard as in
// the field), a 1081-beam laser at 40 Hz and odometry at 50 Hz — for a fixed wall time, on all
// the machine's cores (run it unpinned). Counters: readings dropped per source, CPU in cores
// (user + system over wall time), bag data rate and peak resident memory.

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include <opencv2/imgcodecs.hpp>

#include "bag/sensor_messages.hpp"
#include "capture/recorder.hpp"

namespace littermap {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kRecordSeconds = 20.0;

// Readings at a fixed rate, made by `make(k)`.
class PacedSource : public capture::SensorSource {
 public:
  PacedSource(capture::SensorKind kind, double rate_hz,
              std::function<capture::SensorSample(std::uint64_t)> make)
      : kind_(kind), period_(1.0 / rate_hz), make_(std::move(make)) {}
  capture::SensorKind kind() const override { return kind_; }
  const std::string& uri() const override { return uri_; }
  void Connect() override { next_ = Clock::now(); }
  std::optional<capture::SensorSample> Read(double timeout_s) override {
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(timeout_s));
    if (next_ > deadline) {
      std::this_thread::sleep_until(deadline);
      return std::nullopt;
    }
    std::this_thread::sleep_until(next_);
    next_ += std::chrono::duration_cast<Clock::duration>(period_);
    return make_(k_++);
  }
  void Disconnect() override {}

 private:
  capture::SensorKind kind_;
  std::string uri_ = "bench://paced";
  std::chrono::duration<double> period_;
  std::function<capture::SensorSample(std::uint64_t)> make_;
  Clock::time_point next_;
  std::uint64_t k_ = 0;
};

double CpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

void BM_SustainedCapture(benchmark::State& state) {
  const std::filesystem::path data = std::filesystem::path(LITTERMAP_DATASETS_DIR) / "tum_pair";
  std::vector<cv::Mat> colours, depths;
  for (const char* name : {"1", "2"}) {
    colours.push_back(cv::imread((data / (std::string(name) + ".png")).string(), cv::IMREAD_COLOR));
    depths.push_back(
        cv::imread((data / (std::string(name) + "_depth.png")).string(), cv::IMREAD_UNCHANGED));
    if (colours.back().empty() || depths.back().type() != CV_16UC1) {
      state.SkipWithError("tum_pair images missing");
      return;
    }
  }
  msg::CameraInfo info;
  info.width = 640;
  info.height = 480;
  info.k = {525, 0, 319.5, 0, 525, 239.5, 0, 0, 1};
  LaserScan scan;
  scan.angle_min_rad = -2.356;
  scan.angle_increment_rad = 2 * M_PI / 1440;
  scan.range_max_m = 30;
  scan.ranges_m.resize(1081);

  for (auto _ : state) {
    std::vector<std::unique_ptr<capture::SensorSource>> sources;
    sources.push_back(
        std::make_unique<PacedSource>(capture::SensorKind::kCamera, 30, [&](std::uint64_t k) {
          capture::RgbdFrame frame;  // a driver hands over fresh buffers
          frame.stamp_ns = HostNowNs();
          frame.colour_bgr = colours[k % 2].clone();
          frame.depth_mm = depths[k % 2].clone();
          frame.camera_info = info;
          return capture::SensorSample(std::move(frame));
        }));
    sources.push_back(
        std::make_unique<PacedSource>(capture::SensorKind::kLaser, 40, [&](std::uint64_t k) {
          for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
            scan.ranges_m[i] = static_cast<float>(3 + std::sin(0.01 * static_cast<double>(i + k)));
          }
          return capture::SensorSample(bag::sensor_messages::Scan(HostNowNs(), scan));
        }));
    sources.push_back(
        std::make_unique<PacedSource>(capture::SensorKind::kOdometry, 50, [](std::uint64_t k) {
          const double t = static_cast<double>(k) / 50;
          return capture::SensorSample(
              bag::sensor_messages::Odometry(HostNowNs(), {0.5 * t, 0, 0.01 * t}, 0.5, 0.01));
        }));

    const std::filesystem::path bag = std::filesystem::temp_directory_path() /
                                      ("littermap-capture-bench-" + std::to_string(getpid()));
    std::filesystem::remove_all(bag);
    capture::RecorderOptions options;
    options.max_duration_s = kRecordSeconds;
    const std::atomic<bool> never{false};
    const double cpu_before = CpuSeconds();
    const capture::RecordingResult result =
        capture::Record(bag, std::move(sources), {}, options, never);
    const double cpu_s = CpuSeconds() - cpu_before;
    std::uintmax_t bag_bytes = 0;
    for (const auto& file : std::filesystem::directory_iterator(bag)) bag_bytes += file.file_size();
    std::filesystem::remove_all(bag);

    for (const capture::SourceStatus& source : result.sources) {
      state.counters[source.name + "_hz"] = static_cast<double>(source.written) / result.duration_s;
      state.counters[source.name + "_drop_pct"] =
          source.received == 0
              ? 0.0
              : 100.0 * static_cast<double>(source.dropped) / static_cast<double>(source.received);
      state.counters[source.name + "_queue_max"] = static_cast<double>(source.max_queue_depth);
    }
    state.counters["cpu_cores"] = cpu_s / result.duration_s;
    state.counters["bag_MB_per_s"] = static_cast<double>(bag_bytes) / 1e6 / result.duration_s;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
  }
}
BENCHMARK(BM_SustainedCapture)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
}  // namespace littermap

BENCHMARK_MAIN();
