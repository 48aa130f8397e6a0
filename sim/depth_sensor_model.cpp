#include "sim/depth_sensor_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/procedural_noise.hpp"

namespace littermap::sim {
namespace {

// True when a 4-neighbour is sky or differs in depth by more than `jump` of z.
bool AtEdge(const float* z, int x, int y, int width, int height, float jump) {
  const float centre = z[0], limit = jump * centre;
  const auto differs = [&](const float* n) { return !(std::abs(*n - centre) <= limit); };
  return (x > 0 && differs(z - 1)) || (x + 1 < width && differs(z + 1)) ||
         (y > 0 && differs(z - width)) || (y + 1 < height && differs(z + width));
}

}  // namespace

void ValidateDepthSensorOptions(const DepthSensorOptions& o) {
  const auto require = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("rgbd camera: invalid ") + field);
  };
  require(o.min_depth_m >= 0 && o.max_depth_m > o.min_depth_m, "min_depth_m/max_depth_m");
  require(o.noise_coefficient_per_m >= 0, "noise_coefficient_per_m");
  require(o.disparity_step_px > 0 && o.baseline_m > 0 && o.disparity_focal_px > 0,
          "disparity_step_px/baseline_m/disparity_focal_px");
  require(o.max_incidence_deg > 0 && o.max_incidence_deg <= 90, "max_incidence_deg");
  require(o.edge_jump_fraction > 0, "edge_jump_fraction");
  require(o.edge_dropout_probability >= 0 && o.edge_dropout_probability <= 1,
          "edge_dropout_probability");
}

cv::Mat SimulateDepth(const ZBuffer& zbuffer, const PinholeCamera& camera,
                      const DepthSensorOptions& o, std::uint64_t seed, DepthStats& stats) {
  const int width = zbuffer.width(), height = zbuffer.height();
  cv::Mat depth_mm(height, width, CV_16UC1, cv::Scalar(0));
  stats = {};
  const float min_z = float(o.min_depth_m), max_z = float(o.max_depth_m);
  const float cos_max_incidence = float(std::cos(o.max_incidence_deg * std::numbers::pi / 180));
  const float jump = float(o.edge_jump_fraction), k = float(o.noise_coefficient_per_m);
  const float fb = float(o.disparity_focal_px * o.baseline_m), step = float(o.disparity_step_px);
  const float drop_edge = float(o.edge_dropout_probability);
  const float* z_all = zbuffer.depth_m().data();
  for (int y = 0; y < height; ++y) {
    auto* out = depth_mm.ptr<std::uint16_t>(y);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const float z = z_all[i];
      if (zbuffer.ids()[i] == kSkyInstance || z < min_z || z > max_z) {
        ++stats.out_of_range;
        continue;
      }
      const Eigen::Vector3f ray = camera.Ray(x, y).cast<float>();
      const Eigen::Vector3f& n = zbuffer.normals()[i];
      if (std::abs(n.dot(ray)) < cos_max_incidence * n.norm() * ray.norm()) {
        ++stats.grazing;
        continue;
      }
      const std::uint64_t h = Hash3(seed, i, 0xDE97);
      if (AtEdge(z_all + i, x, y, width, height, jump) && HashToUnit(h) < drop_edge) {
        ++stats.edge;
        continue;
      }
      float measured = z + k * z * z * HashToNormal(HashMix(h));
      if (o.quantise && measured > 0) {
        measured = fb / (std::round(fb / measured / step) * step);
      }
      if (!(measured >= min_z && measured <= max_z)) {
        ++stats.out_of_range;
        continue;
      }
      out[x] = static_cast<std::uint16_t>(std::lround(measured * 1000.0f));
      ++stats.valid;
    }
  }
  return depth_mm;
}

}  // namespace littermap::sim
