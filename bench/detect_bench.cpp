// Speed of litter detection on one 640x480 RGB-D frame of the sample park: ground segmentation
// (thesis 3.1: normals, components, ground, texture learning + graph cut, object refinement)
// and classification of every object with the shipped model. Goal: >= 10 frames/s on one core,
// i.e. <= 100 ms per frame. Run pinned: taskset -c 0 detect_bench

#include <cmath>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "detect/frame_segmenter.hpp"
#include "detect/litter_classifier.hpp"
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

void BM_SegmentAndClassifyFrame(benchmark::State& state) {
  const auto& frames = RouteFrames();
  const auto classifier = detect::LitterClassifier::Load(
      LITTERMAP_SOURCE_DIR "/samples/models/litter_classifier.yml.gz");
  detect::FrameSegmenter segmenter(detect::SegmentationOptions{});
  const detect::CameraIntrinsics K;
  const Eigen::Isometry3f T_level_camera = T_base_optical().cast<float>();
  std::size_t i = 0, objects = 0;
  detect::SegmentationTimings sum;
  for (auto _ : state) {
    const Frame& f = frames[i++ % frames.size()];
    const auto segmentation = segmenter.Segment(f.colour, f.depth_mm, K, T_level_camera);
    for (const auto& object : segmentation.objects) {
      detect::ObjectSample sample;
      sample.colour_bgr = f.colour(object.box);
      sample.mask = object.mask;
      sample.size_m = object.size_m, sample.width_m = object.width_m;
      sample.height_m = object.height_m, sample.range_m = object.range_m;
      benchmark::DoNotOptimize(classifier.Classify(sample).best);
    }
    objects += segmentation.objects.size();
    sum += segmentation.timings;
  }
  const double n = double(i);
  state.counters["frames_per_s"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
  state.counters["objects"] = double(objects) / n;
  state.counters["normals_ms"] = sum.cloud_ms / n;
  state.counters["components_ms"] = sum.components_ms / n;
  state.counters["ground_ms"] = sum.ground_ms / n;
  state.counters["graph_cut_ms"] = sum.texture_ms / n;
  state.counters["objects_ms"] = sum.objects_ms / n;
}
BENCHMARK(BM_SegmentAndClassifyFrame)->Unit(benchmark::kMillisecond)->MinTime(5.0);

}  // namespace
}  // namespace littermap

BENCHMARK_MAIN();
