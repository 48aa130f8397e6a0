#include "sim/scene_tessellation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace littermap::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kFineSegments = 20;
constexpr int kCoarseSegments = 10;

// A primitive of unit size centred on the origin (cylinder along z), with outward normals.
struct UnitMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::array<int, 3>> triangles;

  int Add(const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    positions.push_back(p);
    normals.push_back(n);
    return static_cast<int>(positions.size()) - 1;
  }
};

UnitMesh MakeBox() {
  UnitMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      n[axis] = side;
      const Eigen::Vector3f u = Eigen::Vector3f::Unit((axis + 1) % 3) * 0.5f;
      const Eigen::Vector3f v = Eigen::Vector3f::Unit((axis + 2) % 3) * 0.5f;
      const Eigen::Vector3f c = 0.5f * n;
      const int a = mesh.Add(c - u - v, n), b = mesh.Add(c + u - v, n);
      const int d = mesh.Add(c + u + v, n), e = mesh.Add(c - u + v, n);
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({a, d, e});
    }
  }
  return mesh;
}

UnitMesh MakeCylinder(int segments) {
  UnitMesh mesh;
  for (int cap = 0; cap < 2; ++cap) {  // flat caps as fans
    const float z = cap ? 0.5f : -0.5f;
    const Eigen::Vector3f n(0, 0, cap ? 1.0f : -1.0f);
    const int centre = mesh.Add({0, 0, z}, n);
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * kPi * i / segments;
      mesh.Add({0.5f * float(std::cos(a)), 0.5f * float(std::sin(a)), z}, n);
    }
    for (int i = 0; i < segments; ++i) {
      mesh.triangles.push_back({centre, centre + 1 + i, centre + 1 + (i + 1) % segments});
    }
  }
  const int first = static_cast<int>(mesh.positions.size());
  for (int i = 0; i < segments; ++i) {  // smooth side
    const double a = 2 * kPi * i / segments;
    const Eigen::Vector3f n(float(std::cos(a)), float(std::sin(a)), 0);
    mesh.Add({0.5f * n.x(), 0.5f * n.y(), -0.5f}, n);
    mesh.Add({0.5f * n.x(), 0.5f * n.y(), 0.5f}, n);
  }
  for (int i = 0; i < segments; ++i) {
    const int a = first + 2 * i, b = first + 2 * ((i + 1) % segments);
    mesh.triangles.push_back({a, b, b + 1});
    mesh.triangles.push_back({a, b + 1, a + 1});
  }
  return mesh;
}

UnitMesh MakeSphere(int segments) {
  UnitMesh mesh;
  const int rings = std::max(3, segments / 2);
  for (int r = 0; r <= rings; ++r) {
    const double polar = kPi * r / rings;
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * kPi * i / segments;
      const Eigen::Vector3f n(float(std::sin(polar) * std::cos(a)),
                              float(std::sin(polar) * std::sin(a)), float(std::cos(polar)));
      mesh.Add(0.5f * n, n);
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int i = 0; i < segments; ++i) {
      const int a = r * segments + i, b = r * segments + (i + 1) % segments;
      mesh.triangles.push_back({a, a + segments, b + segments});
      mesh.triangles.push_back({a, b + segments, b});
    }
  }
  return mesh;
}

const UnitMesh& MeshFor(Shape shape, bool fine) {
  static const UnitMesh box = MakeBox();
  static const UnitMesh cylinder[2] = {MakeCylinder(kCoarseSegments), MakeCylinder(kFineSegments)};
  static const UnitMesh sphere[2] = {MakeSphere(kCoarseSegments), MakeSphere(kFineSegments)};
  switch (shape) {
    case Shape::kBox:
      return box;
    case Shape::kCylinder:
      return cylinder[fine];
    case Shape::kEllipsoid:
      return sphere[fine];
  }
  return box;
}

// Heading of the view on the ground plane and the half-width of the angular sector that holds
// every border ray of the image (π when the camera sees the point below itself).
void ViewSector(const Eigen::Matrix3d& R_world_camera, const PinholeCamera& camera,
                double& heading_rad, double& half_width_rad) {
  Eigen::Vector3d forward = R_world_camera.col(2);
  if (forward.head<2>().norm() < 1e-3) forward = -R_world_camera.col(1);
  heading_rad = std::atan2(forward.y(), forward.x());
  const Eigen::Vector3d down_camera = R_world_camera.transpose() * Eigen::Vector3d(0, 0, -1);
  if (down_camera.z() > 0) {
    const Eigen::Vector2d nadir = camera.Project(down_camera);
    if (camera.Contains(nadir.x(), nadir.y())) {
      half_width_rad = kPi;
      return;
    }
  }
  half_width_rad = 0;
  constexpr int kSamples = 8;
  for (int i = 0; i <= kSamples; ++i) {
    const double s = double(i) / kSamples;
    const double w = camera.width - 1.0, h = camera.height - 1.0;
    for (const Eigen::Vector2d& uv : {Eigen::Vector2d(s * w, 0), Eigen::Vector2d(s * w, h),
                                      Eigen::Vector2d(0, s * h), Eigen::Vector2d(w, s * h)}) {
      const Eigen::Vector3d d = R_world_camera * camera.Ray(uv.x(), uv.y());
      const double offset = std::remainder(std::atan2(d.y(), d.x()) - heading_rad, 2 * kPi);
      half_width_rad = std::max(half_width_rad, std::abs(offset));
    }
  }
  half_width_rad = std::min(kPi, half_width_rad + 0.1);
}

}  // namespace

void DrawTerrain(const Terrain& terrain, const Eigen::Isometry3d& T_world_camera,
                 const PinholeCamera& camera, const TessellationOptions& options, double range_m,
                 ZBuffer& zbuffer) {
  const Eigen::Matrix3d R_wc = T_world_camera.linear();
  const Eigen::Matrix3f R_cw = R_wc.transpose().cast<float>();
  const Eigen::Vector3d origin = T_world_camera.translation();
  double heading = 0, half_width = 0;
  ViewSector(R_wc, camera, heading, half_width);
  std::vector<double> rings = {0};
  while (rings.back() < range_m) {
    rings.push_back(rings.back() + options.ring_spacing_m + options.ring_growth * rings.back());
  }
  const int cols = options.ground_columns;
  std::vector<RasterVertex> grid(rings.size() * static_cast<std::size_t>(cols + 1));
  for (std::size_t i = 0; i < rings.size(); ++i) {
    for (int j = 0; j <= cols; ++j) {
      const double angle = heading - half_width + 2 * half_width * j / cols;
      const Eigen::Vector2d p =
          origin.head<2>() + rings[i] * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      const Eigen::Vector2d g = terrain.GradientAt(p);
      const Eigen::Vector3d world(p.x(), p.y(), terrain.HeightAt(p));
      grid[i * std::size_t(cols + 1) + std::size_t(j)] = {
          R_cw * (world - origin).cast<float>(),
          R_cw * Eigen::Vector3f(-float(g.x()), -float(g.y()), 1.0f)};
    }
  }
  for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
    const RasterVertex* near_row = &grid[i * std::size_t(cols + 1)];
    const RasterVertex* far_row = near_row + cols + 1;
    for (int j = 0; j < cols; ++j) {
      zbuffer.DrawTriangle(near_row[j], far_row[j], near_row[j + 1], kGroundInstance);
      zbuffer.DrawTriangle(near_row[j + 1], far_row[j], far_row[j + 1], kGroundInstance);
    }
  }
}

int DrawObjects(const std::vector<WorldObject>& objects, const Eigen::Isometry3d& T_world_camera,
                const PinholeCamera& camera, const TessellationOptions& options, float far_m,
                ZBuffer& zbuffer) {
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  // Frustum side planes through the optical centre, as inward unit normals.
  const double l = camera.cx / camera.fx, r = (camera.width - 1 - camera.cx) / camera.fx;
  const double t = camera.cy / camera.fy, b = (camera.height - 1 - camera.cy) / camera.fy;
  const Eigen::Vector3d planes[4] = {
      Eigen::Vector3d(1, 0, l).normalized(), Eigen::Vector3d(-1, 0, r).normalized(),
      Eigen::Vector3d(0, 1, t).normalized(), Eigen::Vector3d(0, -1, b).normalized()};
  std::vector<RasterVertex> vertices;
  int drawn = 0;
  for (const WorldObject& object : objects) {
    const Eigen::Vector3d centre = T_camera_world * object.center_m;
    const double radius = 0.5 * object.size_m.norm();
    if (centre.z() + radius < 0 || centre.z() - radius > far_m) continue;
    if (std::any_of(std::begin(planes), std::end(planes),
                    [&](const Eigen::Vector3d& n) { return n.dot(centre) < -radius; })) {
      continue;
    }
    const double pixels = camera.fx * object.size() / std::max(centre.z(), 0.1);
    const UnitMesh& mesh = MeshFor(object.shape, pixels > options.fine_min_pixels);
    const Eigen::Matrix3d R_co = T_camera_world.linear() * RotationFromRpy(object.orientation);
    const Eigen::Matrix3f M = (R_co * object.size_m.asDiagonal()).cast<float>();
    // Normals transform with the inverse transpose of the scaling.
    const Eigen::Matrix3f N =
        (R_co * object.size_m.cwiseMax(1e-6).cwiseInverse().asDiagonal()).cast<float>();
    const Eigen::Vector3f offset = centre.cast<float>();
    vertices.resize(mesh.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      vertices[i] = {M * mesh.positions[i] + offset, N * mesh.normals[i]};
    }
    const std::int32_t id = InstanceIdOf(object);
    for (const auto& tri : mesh.triangles) {
      zbuffer.DrawTriangle(vertices[std::size_t(tri[0])], vertices[std::size_t(tri[1])],
                           vertices[std::size_t(tri[2])], id);
    }
    ++drawn;
  }
  return drawn;
}

}  // namespace littermap::sim
