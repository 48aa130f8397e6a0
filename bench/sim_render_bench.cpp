// Speed of the simulated RGB-D camera on the sample park: one 640x480 frame (terrain and object
// rasterisation, shading, depth model) from robot-like poses. Budget: 80 ms per frame on one
// core, so camera and laser together simulate at 10 Hz. Run pinned: taskset -c 0 sim_render_bench

#include <cmath>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "sim/rgbd_camera.hpp"

namespace littermap::sim {
namespace {

World& SampleWorld() {
  static World world =
      GenerateWorld(LoadWorldSpec(LITTERMAP_SOURCE_DIR "/samples/worlds/park_small.yaml"));
  return world;
}

// Poses along the route, camera 0.5 m up and pitched 25° down like the sample robot.
std::vector<Eigen::Isometry3d> RoutePoses(const World& world) {
  Eigen::Matrix3d R_body_optical;
  R_body_optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t i = 0; i + 1 < world.route_m.size(); ++i) {
    const Eigen::Vector2d a = world.route_m[i], b = world.route_m[i + 1];
    const double yaw = std::atan2(b.y() - a.y(), b.x() - a.x());
    for (double s = 0; s < 1; s += 0.25) {
      const Eigen::Vector2d p = a + s * (b - a);
      Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
      T.linear() = RotationFromRpy({0, 25 * std::numbers::pi / 180, yaw}) * R_body_optical;
      T.translation() = Eigen::Vector3d(p.x(), p.y(), world.terrain.HeightAt(p) + 0.5);
      poses.push_back(T);
    }
  }
  return poses;
}

void BM_RenderRgbdFrame(benchmark::State& state) {
  const World& world = SampleWorld();
  const std::vector<Eigen::Isometry3d> poses = RoutePoses(world);
  RgbdCamera camera(world, RgbdCameraOptions{});
  std::size_t i = 0;
  double raster = 0, shade = 0, depth = 0;
  for (auto _ : state) {
    const RgbdRender r = camera.Render(poses[i % poses.size()], i);
    benchmark::DoNotOptimize(r.colour_bgr.data);
    raster += r.stats.raster_ms;
    shade += r.stats.shade_ms;
    depth += r.stats.depth_ms;
    ++i;
  }
  const double n = double(i);
  state.counters["raster_ms"] = raster / n;
  state.counters["shade_ms"] = shade / n;
  state.counters["depth_ms"] = depth / n;
}
BENCHMARK(BM_RenderRgbdFrame)->Unit(benchmark::kMillisecond)->MinTime(3.0);

void BM_RgbdCameraSetup(benchmark::State& state) {
  const World& world = SampleWorld();
  for (auto _ : state) {
    RgbdCamera camera(world, RgbdCameraOptions{});
    benchmark::DoNotOptimize(&camera);
  }
}
BENCHMARK(BM_RgbdCameraSetup)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace littermap::sim

BENCHMARK_MAIN();
