#pragma once
// A software z-buffer rasteriser for the simulated RGB-D camera: triangles given in the camera's
// optical frame are clipped against the near plane, projected with the pinhole model and filled
// with perspective-correct depth (1/z is affine in screen space) and interpolated normals. It
// keeps per pixel only what the deferred shading and the depth model need: optical-axis depth,
// the instance id and the surface normal; the 3D point follows from the depth by back-projection.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sim/camera_model.hpp"

namespace littermap::sim {

// Instance ids written to the buffer (and to RgbdRender::instance_ids).
inline constexpr std::int32_t kSkyInstance = -1;
inline constexpr std::int32_t kGroundInstance = 0;

struct RasterVertex {
  Eigen::Vector3f p_camera;  // optical frame, metres
  Eigen::Vector3f n_camera;  // outward normal, optical frame (need not be unit)
};

class ZBuffer {
 public:
  ZBuffer(const PinholeCamera& camera, float near_m, float far_m);

  // Resets every pixel to "nothing seen" (depth +inf, id kSkyInstance).
  void Clear();
  // Draws one triangle; back faces (average normal pointing away from the viewer) are skipped.
  void DrawTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                    std::int32_t id);

  int width() const { return width_; }
  int height() const { return height_; }
  // Row-major per-pixel buffers of width() * height().
  const std::vector<float>& depth_m() const { return depth_m_; }
  const std::vector<std::int32_t>& ids() const { return ids_; }
  const std::vector<Eigen::Vector3f>& normals() const { return normals_; }
  std::int64_t triangles_drawn() const { return triangles_drawn_; }

 private:
  void Fill(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, std::int32_t id);

  float fx_, fy_, cx_, cy_;
  int width_, height_;
  float near_m_, far_m_;
  std::vector<float> depth_m_;
  std::vector<std::int32_t> ids_;
  std::vector<Eigen::Vector3f> normals_;
  std::int64_t triangles_drawn_ = 0;
};

}  // namespace littermap::sim
