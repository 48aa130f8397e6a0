// Speed of litter detection on one 640x480 RGB-D frame of the sample park: ground segmentation
// (thesis 3.1: normals, components, ground, texture learning + graph cut, object refinement)
// and classification of every object with the shipped model, on simulated park frames and on the
// real desk frames of tum_pair. Goal: the camera's 30 frames/s on one core, i.e. <= 33 ms per
// frame (frames/s = 1000 / ms), split by step. Run pinned: taskset -c 0 detect_bench. Each case
// runs five times: the "min" row is the figure of a quiet core (another process on the machine only
// adds time), the median row says how much the machine's load moved it.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/imgcodecs.hpp>

#include "detect/frame_segmenter.hpp"
#include "detect/litter_classifier.hpp"
#include "detect/options_file.hpp"
#include "sim/rgbd_camera.hpp"

namespace littermap {
namespace {

struct Frame {
  cv::Mat colour, depth_mm;
};

Eigen::Isometry3d T_base_optical() {
  return MakeIsometry({0.2, 0, 0.5}, {0, 25 * std::numbers::pi / 180, 0}) * T_body_optical();
}

// Frames along the sample park's route, camera mounted as on the sample robot.
const std::vector<Frame>& RouteFrames() {
  static const std::vector<Frame> frames = [] {
    const sim::World world = sim::GenerateWorld(
        sim::LoadWorldSpec(LITTERMAP_SOURCE_DIR "/samples/worlds/park_small.yaml"));
    sim::RgbdCamera camera(world, sim::RgbdCameraOptions{});
    std::vector<Frame> out;
    for (std::size_t i = 0; i + 1 < world.route_m.size(); ++i) {
      const Eigen::Vector2d a = world.route_m[i], b = world.route_m[i + 1];
      const double yaw = std::atan2(b.y() - a.y(), b.x() - a.x());
      for (double s = 0; s < 1; s += 0.1) {
        const Eigen::Vector2d p = a + s * (b - a);
        const Eigen::Isometry3d T_world_base =
            MakeIsometry({p.x(), p.y(), world.terrain.HeightAt(p)}, {0, 0, yaw});
        const sim::RgbdRender r = camera.Render(T_world_base * T_base_optical(), out.size());
        out.push_back({r.colour_bgr, r.depth_mm});
      }
    }
    return out;
  }();
  return frames;
}

// Segments and classifies the frames in turn, and reports the time of each step per frame.
void SegmentAndClassify(benchmark::State& state, const std::vector<Frame>& frames,
                        const detect::CameraIntrinsics& K,
                        const Eigen::Isometry3f& T_level_camera) {
  const auto classifier = detect::LitterClassifier::Load(
      LITTERMAP_SOURCE_DIR "/samples/models/litter_classifier.yml.gz");
  // The benchmark's arguments: the normal step (organized_cloud.hpp: 1 = every pixel), the
  // normal method (0 PCL covariance, 1 OpenCV FALS, 2 PCL average 3D gradient) and the options:
  // 0 the defaults (the geometry on every 2nd pixel), 1 samples/detect_full.yaml (on every pixel).
  detect::RunObjectsOptions run_options;
  detect::FusionOptions fusion;
  if (state.range(2) == 1) {
    detect::ApplyOptionsFile(LITTERMAP_SOURCE_DIR "/samples/detect_full.yaml", &run_options,
                             &fusion);
  }
  detect::SegmentationOptions options = run_options.segmentation;
  options.cloud.normal_step_px = static_cast<int>(state.range(0));
  const detect::NormalMethod methods[] = {detect::NormalMethod::kCovariance,
                                          detect::NormalMethod::kFals,
                                          detect::NormalMethod::kAverage3dGradient};
  options.cloud.normal_method = methods[state.range(1)];
  detect::FrameSegmenter segmenter(options);
  std::size_t i = 0, objects = 0, blobs = 0, refined = 0, split = 0, with_ground = 0;
  detect::SegmentationTimings sum;
  double classify_ms = 0;
  for (auto _ : state) {
    const Frame& f = frames[i++ % frames.size()];
    const auto segmentation = segmenter.Segment(f.colour, f.depth_mm, K, T_level_camera);
    const auto start = std::chrono::steady_clock::now();
    for (const auto& object : segmentation.objects) {
      detect::ObjectSample sample;
      sample.colour_bgr = f.colour(object.box);
      sample.mask = object.mask;
      sample.size_m = object.size_m, sample.width_m = object.width_m;
      sample.height_m = object.height_m, sample.range_m = object.range_m;
      benchmark::DoNotOptimize(classifier.Classify(sample).best);
    }
    classify_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    objects += segmentation.objects.size();
    blobs += segmentation.blobs;
    refined += segmentation.refined;
    split += segmentation.split;
    with_ground += segmentation.ground_found ? 1 : 0;
    sum += segmentation.timings;
  }
  const double n = double(i);
  state.counters["ground_found"] = double(with_ground) / n;
  state.counters["blobs"] = double(blobs) / n;
  state.counters["refined"] = double(refined) / n;
  state.counters["split"] = double(split) / n;
  state.counters["objects"] = double(objects) / n;
  state.counters["normals_ms"] = sum.cloud_ms / n;
  state.counters["components_ms"] = sum.components_ms / n;
  state.counters["ground_ms"] = sum.ground_ms / n;
  state.counters["graph_cut_ms"] = sum.texture_ms / n;
  state.counters["objects_ms"] = sum.objects_ms / n;
  state.counters["classify_ms"] = classify_ms / n;
}

double Least(const std::vector<double>& values) {
  return *std::min_element(values.begin(), values.end());
}

void BM_ParkFrames(benchmark::State& state) {
  SegmentAndClassify(state, RouteFrames(), detect::CameraIntrinsics{},
                     T_base_optical().cast<float>());
}
BENCHMARK(BM_ParkFrames)
    ->ArgNames({"normal_step", "method", "full"})
    ->Args({1, 0, 0})
    ->Args({1, 1, 0})
    ->Args({1, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->Repetitions(5)
    ->ComputeStatistics("min", Least)
    ->ReportAggregatesOnly();

// The two real frames of ../shared/datasets/tum_pair (TUM RGB-D freiburg2 desk), the desk top
// taken as the ground: the camera about 0.7 m above it, looking 35 deg down.
void BM_TumDeskFrames(benchmark::State& state) {
  static const std::vector<Frame> frames = [] {
    std::vector<Frame> out;
    for (const std::string name : {"1", "2"}) {
      const std::string stem = LITTERMAP_DATASETS_DIR "/tum_pair/" + name;
      Frame f;
      f.colour = cv::imread(stem + ".png", cv::IMREAD_COLOR);
      cv::imread(stem + "_depth.png", cv::IMREAD_UNCHANGED).convertTo(f.depth_mm, CV_16U, 0.2);
      if (f.colour.empty() || f.depth_mm.empty()) throw std::runtime_error("no tum_pair " + stem);
      out.push_back(f);
    }
    return out;
  }();
  detect::CameraIntrinsics K;
  K.fx = 520.909, K.fy = 521.007, K.cx = 325.141, K.cy = 249.702;
  const Eigen::Isometry3d T_level_optical =
      MakeIsometry({0, 0, 0.7}, {0, 35 * std::numbers::pi / 180, 0}) * T_body_optical();
  SegmentAndClassify(state, frames, K, T_level_optical.cast<float>());
}
BENCHMARK(BM_TumDeskFrames)
    ->ArgNames({"normal_step", "method", "full"})
    ->Args({1, 0, 0})
    ->Args({1, 1, 0})
    ->Args({1, 1, 1})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->Repetitions(5)
    ->ComputeStatistics("min", Least)
    ->ReportAggregatesOnly();

}  // namespace
}  // namespace littermap

BENCHMARK_MAIN();
