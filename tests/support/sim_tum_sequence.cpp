#include "support/sim_tum_sequence.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "sim/rgbd_camera.hpp"
#include "sim/simulation.hpp"
#include "sim/world_spec.hpp"

namespace littermap::test {

std::size_t WriteSimTumSequence(const std::filesystem::path& world_yaml,
                                const std::filesystem::path& directory,
                                const SimTumSequenceOptions& options) {
  const sim::WorldSpec spec = sim::LoadWorldSpec(world_yaml);
  const sim::Simulation simulation(spec, {});
  sim::RgbdCameraOptions camera_options;
  camera_options.output_instance_ids = false;
  camera_options.intrinsics = {535.4, 539.2, 320.1, 247.6, 640, 480};  // freiburg3
  sim::RgbdCamera camera(simulation.world(), camera_options);
  std::filesystem::create_directories(directory / "rgb");
  std::filesystem::create_directories(directory / "depth");
  std::ofstream rgb(directory / "rgb.txt"), depth(directory / "depth.txt"),
      truth(directory / "groundtruth.txt");
  if (!rgb || !depth || !truth) throw std::runtime_error(directory.string() + ": cannot write");
  rgb << "# color images\n# timestamp filename\n";
  depth << "# depth maps\n# timestamp filename\n";
  truth << "# ground truth trajectory\n# timestamp tx ty tz qx qy qz qw\n";
  std::size_t frames = 0;
  const double end_s = std::min(options.duration_s, simulation.duration_s());
  for (double t = 0; t <= end_s; t = static_cast<double>(++frames) / options.rate_hz) {
    const Eigen::Isometry3d T_world_optical = simulation.TrueOpticalPose(t);
    const sim::RgbdRender render = camera.Render(T_world_optical, frames + 1);
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%.6f", 1.3e9 + t);
    const std::string name = std::string(stamp) + ".png";
    cv::Mat depth_tum;  // 5000 units per metre
    render.depth_mm.convertTo(depth_tum, CV_16U, 5.0);
    if (!cv::imwrite((directory / "rgb" / name).string(), render.colour_bgr) ||
        !cv::imwrite((directory / "depth" / name).string(), depth_tum)) {
      throw std::runtime_error(directory.string() + ": cannot write a frame");
    }
    rgb << stamp << " rgb/" << name << '\n';
    depth << stamp << " depth/" << name << '\n';
    const Eigen::Quaterniond q(T_world_optical.linear());
    const Eigen::Vector3d& p = T_world_optical.translation();
    char line[160];
    std::snprintf(line, sizeof line, "%s %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", stamp, p.x(), p.y(),
                  p.z(), q.x(), q.y(), q.z(), q.w());
    truth << line;
  }
  return frames;
}

}  // namespace littermap::test
