// RGB-D alignment (reconstruct/rgbd_aligner.hpp).
//   BM_AlignTumPair/<features>: one whole alignment of the real 640x480 TUM freiburg2 desk pair
//     (goal: ≤ 30 ms on one core with ORB).
//   BM_Rejection/<rejection>: the rejection ablation on simulator frame pairs with known motion
//     (park_small, frames 0.5 s apart along the route): precision of the kept pairs (a pair is
//     good when the true motion maps it within 5 cm), final pose error, the share of pairs of
//     frames aligned, and the time of rejection + SVD + ICP over all of them (Time column).

#include <benchmark/benchmark.h>

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "reconstruct/rgbd_aligner.hpp"
#include "sim/rgbd_camera.hpp"
#include "sim/simulation.hpp"
#include "sim/world_spec.hpp"

namespace littermap::reconstruct {
namespace {

const std::filesystem::path kDatasets = LITTERMAP_DATASETS_DIR;

void BM_AlignTumPair(benchmark::State& state) {
  RgbdImage images[2];
  for (int i = 0; i < 2; ++i) {
    const std::string name = std::to_string(i + 1);
    images[i].colour_bgr = cv::imread((kDatasets / "tum_pair" / (name + ".png")).string());
    images[i].depth =
        cv::imread((kDatasets / "tum_pair" / (name + "_depth.png")).string(), cv::IMREAD_UNCHANGED);
    images[i].depth_unit_m = 1.0 / 5000;
    if (images[i].colour_bgr.empty()) {
      state.SkipWithError("tum_pair missing");
      return;
    }
  }
  const RgbdCameraModel camera{520.909, 521.007, 325.141, 249.702, {}};
  RgbdAlignerOptions options;
  options.features = static_cast<RgbdFeatures>(state.range(0));
  const RgbdAligner aligner(options);
  RgbdAlignment result;
  for (auto _ : state) {
    result = aligner.Align(images[0], images[1], camera);
    benchmark::DoNotOptimize(result);
  }
  state.SetLabel(options.features == RgbdFeatures::kOrb    ? "ORB"
                 : options.features == RgbdFeatures::kSift ? "SIFT"
                                                           : "AKAZE");
  state.counters["pairs"] = result.pairs;
  state.counters["kept"] = result.pairs_kept;
  state.counters["inlier_ratio"] = result.icp_inlier_ratio;
}
BENCHMARK(BM_AlignTumPair)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

struct KnownPair {
  RgbdPairs pairs;
  Eigen::Isometry3d T_keyframe_frame;
};

// Frame pairs 0.5 s apart every 10 s of the park_small route, matched once with ORB.
const std::vector<KnownPair>& SimulatorPairs() {
  static const std::vector<KnownPair> pairs = [] {
    const sim::WorldSpec spec = sim::LoadWorldSpec(std::filesystem::path(LITTERMAP_SOURCE_DIR) /
                                                   "samples/worlds/park_small.yaml");
    const sim::Simulation simulation(spec, {});
    sim::RgbdCameraOptions camera_options;
    camera_options.output_instance_ids = false;
    sim::RgbdCamera camera(simulation.world(), camera_options);
    const sim::PinholeCamera& k = camera_options.intrinsics;
    const RgbdCameraModel model{k.fx, k.fy, k.cx, k.cy, {}};
    const RgbdAligner matcher;
    std::vector<KnownPair> out;
    std::uint64_t seed = 0;
    for (double t = 5; t + 0.5 < simulation.duration_s(); t += 10) {
      const Eigen::Isometry3d T_world_kf = simulation.TrueOpticalPose(t);
      const Eigen::Isometry3d T_world_f = simulation.TrueOpticalPose(t + 0.5);
      const sim::RgbdRender a = camera.Render(T_world_kf, ++seed);
      const sim::RgbdRender b = camera.Render(T_world_f, ++seed);
      const RgbdImage kf{a.colour_bgr, a.depth_mm, 0.001}, f{b.colour_bgr, b.depth_mm, 0.001};
      out.push_back({matcher.Match(matcher.Extract(kf, model), matcher.Extract(f, model)),
                     T_world_kf.inverse() * T_world_f});
    }
    return out;
  }();
  return pairs;
}

void BM_Rejection(benchmark::State& state) {
  RgbdAlignerOptions options;
  options.rejection = static_cast<PairRejection>(state.range(0));
  const RgbdAligner aligner(options);
  const std::vector<KnownPair>& pairs = SimulatorPairs();
  double precision_sum = 0, translation_sum = 0, rotation_sum = 0;
  int aligned = 0, with_kept = 0;
  for (auto _ : state) {
    precision_sum = translation_sum = rotation_sum = 0;
    aligned = with_kept = 0;
    for (const KnownPair& known : pairs) {
      const std::vector<int> kept = aligner.RejectPairs(known.pairs.p, known.pairs.q);
      const RgbdAlignment result = aligner.AlignPairs(known.pairs.p, known.pairs.q);
      if (!kept.empty()) {
        int good = 0;
        for (const int i : kept) {
          const auto& p = known.pairs.p[static_cast<std::size_t>(i)];
          const auto& q = known.pairs.q[static_cast<std::size_t>(i)];
          good += (p - known.T_keyframe_frame * q).norm() < 0.05 ? 1 : 0;
        }
        precision_sum += static_cast<double>(good) / static_cast<double>(kept.size());
        ++with_kept;
      }
      if (!result.ok) continue;
      const Eigen::Isometry3d error = known.T_keyframe_frame.inverse() * result.T_keyframe_frame;
      translation_sum += error.translation().norm();
      rotation_sum += Eigen::AngleAxisd(error.linear()).angle() * 180 / M_PI;
      ++aligned;
    }
  }
  state.SetLabel(options.rejection == PairRejection::kCircularHistogram ? "circular histogram"
                 : options.rejection == PairRejection::kRansac          ? "RANSAC"
                                                                        : "none");
  state.counters["frame_pairs"] = static_cast<double>(pairs.size());
  state.counters["aligned_pct"] = 100.0 * aligned / static_cast<double>(pairs.size());
  state.counters["kept_precision"] = with_kept ? precision_sum / with_kept : 0;
  state.counters["err_cm"] = aligned ? 100 * translation_sum / aligned : 0;
  state.counters["err_deg"] = aligned ? rotation_sum / aligned : 0;
}
BENCHMARK(BM_Rejection)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace littermap::reconstruct

BENCHMARK_MAIN();
