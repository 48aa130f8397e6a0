#include "sim/ground_map.hpp"

#include <algorithm>
#include <cmath>

#include "sim/procedural_noise.hpp"
#include "sim/surface_shading.hpp"

namespace littermap::sim {
namespace {

constexpr double kShadowMarginM = 10;    // shadows fall outside the park too
constexpr double kMaxCells = 4e6;        // caps memory for very large parks
constexpr float kLeafOcclusion = 0.75f;  // a crown passes a quarter of the sun
constexpr float kSolidOcclusion = 0.95f;
constexpr std::uint8_t kBorderCell = 0x80;  // flag in types_: a neighbour has another type

bool Inside(Shape shape, const Eigen::Vector3d& q) {  // q in units of the half-extents
  switch (shape) {
    case Shape::kBox:
      return true;
    case Shape::kCylinder:
      return q.head<2>().squaredNorm() <= 1;
    case Shape::kEllipsoid:
      return q.squaredNorm() <= 1;
  }
  return true;
}

}  // namespace

GroundMap::GroundMap(const World& world, const Eigen::Vector3d& sun_direction_world) {
  const double sx = world.spec.size_x_m, sy = world.spec.size_y_m;
  type_cell_m_ = static_cast<float>(std::max(0.025, std::sqrt(sx * sy / kMaxCells)));
  type_cols_ = static_cast<int>(std::ceil(sx / type_cell_m_));
  type_rows_ = static_cast<int>(std::ceil(sy / type_cell_m_));
  types_.resize(static_cast<std::size_t>(type_cols_) * static_cast<std::size_t>(type_rows_));
  for (int r = 0; r < type_rows_; ++r) {
    for (int c = 0; c < type_cols_; ++c) {
      const Eigen::Vector2d p((c + 0.5) * type_cell_m_, (r + 0.5) * type_cell_m_);
      types_[static_cast<std::size_t>(r * type_cols_ + c)] = static_cast<std::uint8_t>(
          world.terrain.GroundAt(RaggedGroundPoint(float(p.x()), float(p.y())).cast<double>()));
    }
  }
  MarkBorders();
  origin_x_m_ = static_cast<float>(-kShadowMarginM);
  origin_y_m_ = static_cast<float>(-kShadowMarginM);
  const double wx = sx + 2 * kShadowMarginM, wy = sy + 2 * kShadowMarginM;
  shadow_cell_m_ = static_cast<float>(std::max(0.1, std::sqrt(wx * wy / kMaxCells)));
  shadow_cols_ = static_cast<int>(std::ceil(wx / shadow_cell_m_));
  shadow_rows_ = static_cast<int>(std::ceil(wy / shadow_cell_m_));
  sunlight_.assign(static_cast<std::size_t>(shadow_cols_) * static_cast<std::size_t>(shadow_rows_),
                   0.0f);
  const Eigen::Vector3d sun = sun_direction_world.normalized();
  if (sun.z() > 0.05) {  // a sun at the horizon casts no meaningful shadows
    for (const WorldObject& object : world.objects) {
      if (object.kind == ObjectKind::kLitter || object.kind == ObjectKind::kNatural) continue;
      CastShadow(world, object, sun);
    }
  }
  BakeSunlight();
}

float CloudLight(float x, float y) {
  const float cloud =
      std::clamp((ValueNoise(x * 0.05f, y * 0.05f, 92) - 0.55f) / 0.25f, 0.0f, 1.0f);
  return 1 - 0.45f * cloud * cloud * (3 - 2 * cloud);
}

// Occlusion → sunlight, with sun flecks under crowns (gaps between leaves, ~20 cm) and clouds.
void GroundMap::BakeSunlight() {
  for (int row = 0; row < shadow_rows_; ++row) {
    for (int col = 0; col < shadow_cols_; ++col) {
      const float x = origin_x_m_ + float(col) * shadow_cell_m_;
      const float y = origin_y_m_ + float(row) * shadow_cell_m_;
      float& cell = sunlight_[static_cast<std::size_t>(row * shadow_cols_ + col)];
      const float dapple = cell > 0 ? ValueNoise(x * 5, y * 5, 91) : 0.5f;
      cell = (1 - std::min(1.0f, cell * (0.8f + 0.5f * (dapple - 0.5f)))) * CloudLight(x, y);
    }
  }
}

// Samples the primitive on a lattice and stamps a disk where each sample's shadow lands.
void GroundMap::CastShadow(const World& world, const WorldObject& object,
                           const Eigen::Vector3d& sun) {
  const Eigen::Vector3d half = 0.5 * object.size_m;
  const double step = std::clamp(std::min(object.size_m.x(), object.size_m.y()), 0.1, 0.5);
  const int nx = std::max(1, static_cast<int>(std::ceil(object.size_m.x() / step)));
  const int ny = std::max(1, static_cast<int>(std::ceil(object.size_m.y() / step)));
  const int nz = std::max(1, static_cast<int>(std::ceil(object.size_m.z() / 0.2)));
  const Eigen::Matrix3d R = RotationFromRpy(object.orientation);
  const double ground = world.terrain.HeightAt(object.center_m.head<2>());
  const float occlusion = object.texture == "leaves" ? kLeafOcclusion : kSolidOcclusion;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) {
        const Eigen::Vector3d q(2 * (i + 0.5) / nx - 1, 2 * (j + 0.5) / ny - 1,
                                2 * (k + 0.5) / nz - 1);
        if (!Inside(object.shape, q)) continue;
        const Eigen::Vector3d p = object.center_m + R * q.cwiseProduct(half);
        const double above = p.z() - ground;
        if (above < 0) continue;
        Stamp(p.head<2>() - sun.head<2>() * (above / sun.z()), 0.6 * step, occlusion);
      }
    }
  }
}

void GroundMap::Stamp(const Eigen::Vector2d& centre_m, double radius_m, float occlusion) {
  const double cx = (centre_m.x() - origin_x_m_) / shadow_cell_m_;
  const double cy = (centre_m.y() - origin_y_m_) / shadow_cell_m_;
  const double r = radius_m / shadow_cell_m_;
  const int c0 = std::max(0, static_cast<int>(std::floor(cx - r)));
  const int c1 = std::min(shadow_cols_ - 1, static_cast<int>(std::ceil(cx + r)));
  const int r0 = std::max(0, static_cast<int>(std::floor(cy - r)));
  const int r1 = std::min(shadow_rows_ - 1, static_cast<int>(std::ceil(cy + r)));
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      if ((col - cx) * (col - cx) + (row - cy) * (row - cy) > r * r) continue;
      float& cell = sunlight_[static_cast<std::size_t>(row * shadow_cols_ + col)];
      cell = std::max(cell, occlusion);
    }
  }
}

std::uint8_t GroundMap::Cell(float x, float y) const {
  const int c = FastFloor(x / type_cell_m_);
  const int r = FastFloor(y / type_cell_m_);
  if (c < 0 || r < 0 || c >= type_cols_ || r >= type_rows_) {
    return static_cast<std::uint8_t>(GroundType::kGrass);
  }
  return types_[static_cast<std::size_t>(r * type_cols_ + c)];
}

void GroundMap::MarkBorders() {
  std::vector<std::uint8_t> marked = types_;
  for (int r = 0; r < type_rows_; ++r) {
    for (int c = 0; c < type_cols_; ++c) {
      const std::uint8_t type = types_[static_cast<std::size_t>(r * type_cols_ + c)];
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int rr = std::clamp(r + dr, 0, type_rows_ - 1);
          const int cc = std::clamp(c + dc, 0, type_cols_ - 1);
          if (types_[static_cast<std::size_t>(rr * type_cols_ + cc)] != type) {
            marked[static_cast<std::size_t>(r * type_cols_ + c)] |= kBorderCell;
          }
        }
      }
    }
  }
  types_ = std::move(marked);
}

GroundType GroundMap::TypeAt(float x, float y) const {
  std::uint8_t cell = Cell(x, y);
  if (cell & kBorderCell) {
    // Near a region border a sub-cell wobble of the look-up (±0.6 cells) hides the cells, which
    // would show as stair steps close to the camera. Interior cells, nearly all, skip the noise;
    // the wobble stays within the 8 neighbours that made the cell a border cell.
    const float frequency = 1 / (0.7f * type_cell_m_), amplitude = 1.2f * type_cell_m_;
    const float wx = amplitude * (ValueNoise(x * frequency, y * frequency, 61) - 0.5f);
    const float wy = amplitude * (ValueNoise(x * frequency, y * frequency, 62) - 0.5f);
    cell = Cell(x + wx, y + wy);
  }
  return static_cast<GroundType>(cell & ~kBorderCell);
}

float GroundMap::SunlightAt(float x, float y) const {
  const float gx = (x - origin_x_m_) / shadow_cell_m_, gy = (y - origin_y_m_) / shadow_cell_m_;
  const int c = FastFloor(gx), r = FastFloor(gy);
  const float fx = static_cast<float>(c), fy = static_cast<float>(r);
  if (c < 0 || r < 0 || c + 1 >= shadow_cols_ || r + 1 >= shadow_rows_) return CloudLight(x, y);
  const float tx = gx - fx, ty = gy - fy;
  const float* row0 = &sunlight_[static_cast<std::size_t>(r * shadow_cols_ + c)];
  const float* row1 = row0 + shadow_cols_;
  const float top = row0[0] + (row0[1] - row0[0]) * tx;
  const float bottom = row1[0] + (row1[1] - row1[0]) * tx;
  return top + (bottom - top) * ty;
}

}  // namespace littermap::sim
