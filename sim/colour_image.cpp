#include "sim/colour_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/procedural_noise.hpp"

namespace littermap::sim {
namespace {

constexpr int kLutSize = 4096;

// Linear 0..1 → 8-bit sRGB (IEC 61966-2-1), as a camera's output encoding.
const std::array<float, kLutSize + 1>& SrgbLut() {
  static const std::array<float, kLutSize + 1> lut = [] {
    std::array<float, kLutSize + 1> t{};
    for (int i = 0; i <= kLutSize; ++i) {
      const double v = double(i) / kLutSize;
      const double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
      t[std::size_t(i)] = float(255 * s);
    }
    return t;
  }();
  return lut;
}

struct Frame {
  Eigen::Matrix3f R_wc;
  Eigen::Vector3f t_wc, sun_camera, up_camera;
};

// Clear plastic (Fresnel with Schlick's approximation, n = 1.5): the share F reflected shows the
// sky in the mirror direction (the ground below the horizon), the rest passes in, where the
// share `transmission` lets through what lies behind and the rest is the plastic's own pale
// scattering. Behind is the ground where the view ray meets it under the object (a few cm past
// a bottle lying on it; refraction ignored), lit as ground. Mud on the plastic (a lower
// transmission in the sample than the object's) neither lets through nor mirrors.
Eigen::Vector3f SeeThrough(const ColourScene& scene, const ObjectSurface& object,
                           const SurfaceSample& s, const Eigen::Vector3f& own,
                           const Eigen::Vector3f& p_world, const Eigen::Vector3f& view_world,
                           const Eigen::Vector3f& n_world, float footprint) {
  const Eigen::Vector3f ray = -view_world;
  const float drop = p_world.z() - object.ground_z_m;
  const float t = ray.z() < -0.05f ? std::clamp(drop / -ray.z(), 0.0f, 0.5f) : 0.0f;
  const Eigen::Vector3f q = p_world + t * ray;
  const float cos_view = std::clamp(n_world.dot(view_world), 0.0f, 1.0f);
  // The ground is seen more obliquely than the plastic: a larger footprint on it.
  const float ground_footprint =
      std::min(1.0f, footprint * std::max(0.1f, cos_view) / std::max(0.1f, -ray.z()));
  const Eigen::Vector3f albedo =
      GroundAlbedo(scene.ground.TypeAt(q.x(), q.y()), q.x(), q.y(), ground_footprint);
  const Lighting& l = scene.lighting;
  const float sun_up = std::max(0.0f, float(l.sun_direction_world.normalized().z()));
  const Eigen::Vector3f behind =
      albedo *
      (l.sky_irradiance + l.sun_irradiance * scene.ground.SunlightAt(q.x(), q.y()) * sun_up);
  const Eigen::Vector3f mirror = 2 * n_world.dot(view_world) * n_world - view_world;
  const Eigen::Vector3f reflected = mirror.z() > 0 ? SkyColour(mirror.normalized()) : behind;
  const float m = 1 - cos_view;
  const float clean = s.transmission / object.transmission;
  const float fresnel = (0.04f + 0.96f * m * m * m * m * m) * clean;
  const Eigen::Vector3f entering = own + (behind - own) * s.transmission;
  return entering + (reflected - entering) * fresnel;
}

Eigen::Vector3f ShadeSurface(const ZBuffer& zb, const PinholeCamera& camera, const Frame& f,
                             const ColourScene& scene, std::size_t i, const Eigen::Vector3f& ray) {
  const float z = zb.depth_m()[i];
  const Eigen::Vector3f p_camera = ray * z;
  const Eigen::Vector3f p_world = f.R_wc * p_camera + f.t_wc;
  const float distance = p_camera.norm();
  const Eigen::Vector3f view = -p_camera / distance;
  Eigen::Vector3f n = zb.normals()[i].normalized();
  if (n.dot(view) < 0) n = -n;  // interpolated normals at silhouettes
  const float footprint = std::min(1.0f, z / float(camera.fx) / std::max(0.1f, n.dot(view)));
  const std::int32_t id = zb.ids()[i];
  SurfaceSample s;
  float above = 0;
  if (id == kGroundInstance) {
    // Region borders were made ragged when the ground map was built.
    const GroundType type = scene.ground.TypeAt(p_world.x(), p_world.y());
    s.albedo = GroundAlbedo(type, p_world.x(), p_world.y(), footprint);
  } else {
    const ObjectSurface& object = scene.surfaces[std::size_t(id - 1)];
    s = ShadeObject(object, p_world, footprint);
    above = p_world.z() - object.ground_z_m;
  }
  const Lighting& l = scene.lighting;
  // The ground's shadow map holds for small objects and the feet of large ones; it fades out over
  // the first metre up, above which only clouds shade (a crown's shadow falls beside it).
  const float up = std::clamp(above, 0.0f, 1.0f);
  const float on_ground = up < 1 ? scene.ground.SunlightAt(p_world.x(), p_world.y()) : 0;
  const float aloft = up > 0 ? CloudLight(p_world.x(), p_world.y()) : 0;
  const float sun = l.sun_irradiance * (on_ground + (aloft - on_ground) * up);
  const float lambert = std::max(0.0f, n.dot(f.sun_camera));
  const float sky = l.sky_irradiance * (0.7f + 0.3f * n.dot(f.up_camera));
  Eigen::Vector3f c = s.albedo * (sky + sun * lambert);
  if (s.transmission > 0) {
    const ObjectSurface& object = scene.surfaces[std::size_t(id - 1)];
    c = SeeThrough(scene, object, s, c, p_world, f.R_wc * view, f.R_wc * n, footprint);
  }
  if (s.specular > 0 && lambert > 0) {
    const float nh = std::max(0.0f, n.dot((f.sun_camera + view).normalized()));
    c += Eigen::Vector3f::Constant(s.specular * sun * std::pow(nh, s.shininess));
  }
  // Haze d / (d + d0): like 1 - exp(-d / d0) for d ≪ d0, without the exp.
  const float haze = distance / (distance + l.haze_distance_m);
  return c + (HorizonColour() - c) * haze;
}

}  // namespace

cv::Mat ShadeColour(const ZBuffer& zbuffer, const PinholeCamera& camera,
                    const Eigen::Isometry3d& T_world_camera, const ColourScene& scene,
                    double noise_sigma_dn, std::uint64_t seed) {
  Frame f;
  f.R_wc = T_world_camera.linear().cast<float>();
  f.t_wc = T_world_camera.translation().cast<float>();
  f.sun_camera = f.R_wc.transpose() * scene.lighting.sun_direction_world.normalized().cast<float>();
  f.up_camera = f.R_wc.transpose() * Eigen::Vector3f::UnitZ();
  const auto& lut = SrgbLut();
  const float sigma = float(noise_sigma_dn);
  const auto& normal = NormalTable();
  const float cx = float(camera.cx), cy = float(camera.cy);
  const float inv_half_diagonal = 1 / std::hypot(cx, cy);
  const int width = zbuffer.width(), height = zbuffer.height();
  cv::Mat bgr(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    auto* out = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const Eigen::Vector3f ray = camera.Ray(x, y).cast<float>();
      const Eigen::Vector3f c = zbuffer.ids()[i] == kSkyInstance
                                    ? SkyColour((f.R_wc * ray).normalized())
                                    : ShadeSurface(zbuffer, camera, f, scene, i, ray);
      // Lens vignetting: corners about 12 % darker, like the Kinect's colour camera.
      const float du = (float(x) - cx) * inv_half_diagonal,
                  dv = (float(y) - cy) * inv_half_diagonal;
      const float vignette = 1 - 0.12f * (du * du + dv * dv);
      const std::uint64_t h = HashMix(seed ^ (i * 0x9E3779B97F4A7C15ull));
      for (int ch = 0; ch < 3; ++ch) {
        const float linear = std::clamp(c[ch] * vignette, 0.0f, 1.0f);
        float v = lut[std::size_t(linear * kLutSize)];
        v += sigma * normal[(h >> (12 * ch)) & 4095];
        out[x][2 - ch] = static_cast<std::uint8_t>(std::clamp(v + 0.5f, 0.0f, 255.0f));
      }
    }
  }
  return bgr;
}

}  // namespace littermap::sim
