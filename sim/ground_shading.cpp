// Ground and sky colours of the simulated camera (declared in sim/surface_shading.hpp).
// Albedos are rough linear-RGB values of real surfaces: lawn grass 0.05–0.25 per channel, dry
// soil ≈ 0.2–0.3, fallen leaves orange-brown, gravel mid grey.

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/procedural_noise.hpp"
#include "sim/surface_shading.hpp"

namespace littermap::sim {
namespace {

using Colour = Eigen::Vector3f;

float Smoothstep(float a, float b, float x) {
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

// Contrast of a per-cell hash pattern of cell size `cell_m`, faded out where a pixel covers a
// cell or more (the pattern then averages to its mean).
float CellFade(float footprint_m, float cell_m) {
  return std::clamp(1.5f - footprint_m / cell_m, 0.0f, 1.0f);
}

// 64 unit vectors evenly around the circle: random orientations without a sincos per pixel.
const std::array<Eigen::Vector2f, 64>& Directions() {
  static const std::array<Eigen::Vector2f, 64> directions = [] {
    std::array<Eigen::Vector2f, 64> d;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double a = 2 * 3.14159265358979 * double(i) / double(d.size());
      d[i] = {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a))};
    }
    return d;
  }();
  return directions;
}

// An elliptical blob in a jittered lattice cell (pebbles, leaves, grass blades): the blob's hash
// when (x, y) lies inside the ellipse of the cell's blob, else 0. `fill` is the blob's semi-major
// axis in cells (< 0.5), `aspect` its minor/major ratio; its orientation is random. `r2` gets
// the squared elliptical radius of (x, y) (0 at the blob's centre, 1 on its rim) when given.
std::uint64_t Blob(float x, float y, float cell_m, float fill, float aspect, std::uint64_t salt,
                   float* r2 = nullptr) {
  const float gx = x / cell_m, gy = y / cell_m;
  const int ix = FastFloor(gx), iy = FastFloor(gy);
  const float fx = static_cast<float>(ix), fy = static_cast<float>(iy);
  const std::uint64_t h = CellHash64(ix, iy, salt);
  const float margin = 0.5f - fill;  // the blob stays inside its cell
  const float cx = 0.5f + margin * (2 * HashToUnit(h) - 1);
  const float cy = 0.5f + margin * (2 * HashToUnit(h << 24) - 1);
  const Eigen::Vector2f& direction = Directions()[(h >> 10) & 63];
  const float c = direction.x(), s = direction.y();
  const float dx = gx - fx - cx, dy = gy - fy - cy;
  const float a = (c * dx + s * dy) / fill, b = (-s * dx + c * dy) / (aspect * fill);
  const float radius2 = a * a + b * b;
  if (r2 != nullptr) *r2 = radius2;
  return radius2 <= 1 ? (h | 1) : 0;
}

Colour Grass(float x, float y, float fp) {
  const float patch = Fbm(x, y, 0.3f, 2, fp, 11);
  const Colour lush(0.05f, 0.14f, 0.02f), dry(0.17f, 0.19f, 0.05f);
  Colour c = lush + (dry - lush) * Smoothstep(0.45f, 0.8f, patch);
  const float clump = FilteredNoise(x * 9, y * 9, fp * 9, 12);
  const float tufts = 0.6f * FilteredNoise(x * 45, y * 45, fp * 45, 13) +
                      0.4f * FilteredNoise(x * 110, y * 110, fp * 110, 14);
  // Lit tufts are yellower, the gaps between them dark.
  const float b = 0.45f + 1.1f * tufts;
  c = c.cwiseProduct(Colour(b * 1.05f, b, b * 0.8f)) * (0.75f + 0.5f * clump);
  // Single blades near the camera: thin bright strokes in random directions, two layers.
  const float fade = CellFade(fp, 0.004f);
  if (fade > 0) {
    for (int layer = 0; layer < 2; ++layer) {
      const float shift = 0.011f * float(layer);
      const std::uint64_t h = Blob(x + shift, y - shift, 0.03f, 0.45f, 0.12f, 15 + layer);
      if (h == 0) continue;
      const float tone = 1.2f + 0.8f * HashToUnit(h >> 5);
      c += (c.cwiseProduct(Colour(tone * 1.15f, tone, tone * 0.7f)) - c) * fade;
      break;
    }
  }
  return c;
}

Colour DirtPath(float x, float y, float fp) {
  const float tone = Fbm(x, y, 0.6f, 3, fp, 21);
  Colour c = Colour(0.24f, 0.16f, 0.09f) * (0.75f + 0.5f * tone);
  c *= (0.85f + 0.3f * FilteredNoise(x * 60, y * 60, fp * 60, 22)) *
       (0.85f + 0.3f * FilteredNoise(x * 5, y * 5, fp * 5, 24));
  const float fade = CellFade(fp, 0.012f);
  if (fade > 0) {  // scattered small pebbles of a few kinds of stone
    const std::uint64_t h =
        Blob(x, y, 0.03f, 0.1f + 0.25f * ValueNoise(x * 3, y * 3, 25), 0.7f, 23);
    if (h != 0 && HashToUnit(h >> 3) < 0.1f) {
      static const Colour kStones[] = {
          {0.36f, 0.33f, 0.28f}, {0.25f, 0.22f, 0.18f}, {0.45f, 0.40f, 0.33f}};
      const float b = 0.7f + 0.5f * HashToUnit(h >> 9);
      c += (kStones[(h >> 20) % 3] * b - c) * fade;
    }
  }
  return c;
}

// Fallen leaves: three offset layers of randomly oriented elliptical leaves over dark soil.
Colour LeafLitter(float x, float y, float fp) {
  static const Colour kLeaves[] = {{0.30f, 0.15f, 0.05f}, {0.38f, 0.20f, 0.07f},
                                   {0.22f, 0.12f, 0.05f}, {0.45f, 0.22f, 0.06f},
                                   {0.42f, 0.31f, 0.10f}, {0.26f, 0.17f, 0.08f}};
  const Colour soil(0.08f, 0.05f, 0.03f), mean(0.27f, 0.15f, 0.06f);
  const float fade = CellFade(fp, 0.03f);
  Colour c = mean;
  if (fade > 0) {
    c = soil;
    const float warp = 0.006f * (ValueNoise(x * 40, y * 40, 31) - 0.5f);
    // Layers on lattices turned 0°, 35° and 70° with different cell sizes, so no cell borders
    // line up into a visible grid.
    static const float kCos[] = {1.0f, 0.819f, 0.342f}, kSin[] = {0.0f, 0.574f, 0.940f};
    for (int layer = 0; layer < 3; ++layer) {  // the top layer is tested first
      const float u = kCos[layer] * x + kSin[layer] * y + warp;
      const float v = -kSin[layer] * x + kCos[layer] * y;
      const float cell = 0.045f + 0.008f * float(layer);
      float r2 = 0;
      const std::uint64_t h = Blob(u, v, cell, 0.45f, 0.6f, 33 + std::uint64_t(layer), &r2);
      if (h != 0) {  // curled leaves: darker towards the rim
        c = kLeaves[(h >> 8) % 6] * ((0.8f + 0.4f * HashToUnit(h >> 3)) * (1 - 0.3f * r2));
        break;
      }
    }
    c = mean + (c - mean) * fade;
  }
  return c * (0.8f + 0.4f * Fbm(x, y, 0.5f, 2, fp, 34));
}

// Rounded pebbles of 1-3 cm on three lattices of different cell sizes turned 0°, 50° and 105°
// (no grid lines up), brighter at their tops than at their rims, in greys from bluish to warm,
// with dark fines in the gaps. kPebbleGain is set so that the pattern averages to `mean`, the
// colour it fades to far away (measured over 4 m x 4 m: within 2 %).
Colour Gravel(float x, float y, float fp) {
  constexpr float kPebbleGain = 1.27f;
  const Colour mean(0.30f, 0.29f, 0.27f), fines(0.13f, 0.12f, 0.11f);
  const float fade = CellFade(fp, 0.02f);
  Colour c = mean;
  if (fade > 0) {
    c = fines;
    static const float kCos[] = {1.0f, 0.643f, -0.259f}, kSin[] = {0.0f, 0.766f, 0.966f};
    static const float kCell[] = {0.019f, 0.025f, 0.032f}, kFill[] = {0.40f, 0.36f, 0.44f};
    static const float kAspect[] = {0.8f, 0.6f, 0.7f};
    for (int layer = 0; layer < 3; ++layer) {  // the top layer is tested first
      const float u = kCos[layer] * x + kSin[layer] * y, v = -kSin[layer] * x + kCos[layer] * y;
      float r2 = 0;
      const std::uint64_t h = Blob(u, v, kCell[layer], kFill[layer], kAspect[layer],
                                   44 + std::uint64_t(layer), &r2);
      if (h != 0) {
        const float b = 0.55f + 0.9f * HashToUnit(h << 12), warm = 0.85f + 0.3f * HashToUnit(h << 36);
        c = (kPebbleGain * b * (1.15f - 0.4f * r2)) *
            mean.cwiseProduct(Colour(warm, 1.0f, 2.0f - warm));
        break;
      }
    }
    c = mean + (c - mean) * fade;
  }
  return c * (0.85f + 0.3f * Fbm(x, y, 0.8f, 2, fp, 43));
}

}  // namespace

Eigen::Vector2f RaggedGroundPoint(float x, float y) {
  const float dx = 0.25f * (ValueNoise(x * 2, y * 2, 51) - 0.5f) +
                   0.06f * (ValueNoise(x * 12, y * 12, 52) - 0.5f);
  const float dy = 0.25f * (ValueNoise(x * 2, y * 2, 53) - 0.5f) +
                   0.06f * (ValueNoise(x * 12, y * 12, 54) - 0.5f);
  return {x + dx, y + dy};
}

Eigen::Vector3f GroundAlbedo(GroundType type, float x, float y, float footprint_m) {
  switch (type) {
    case GroundType::kGrass:
      return Grass(x, y, footprint_m);
    case GroundType::kDirtPath:
      return DirtPath(x, y, footprint_m);
    case GroundType::kLeafLitter:
      return LeafLitter(x, y, footprint_m);
    case GroundType::kGravel:
      return Gravel(x, y, footprint_m);
  }
  return Grass(x, y, footprint_m);
}

Eigen::Vector3f HorizonColour() { return {0.62f, 0.70f, 0.80f}; }

Eigen::Vector3f SkyColour(const Eigen::Vector3f& d) {
  const float elevation = std::max(d.z(), 0.0f);
  const Colour zenith(0.18f, 0.33f, 0.70f);
  Colour c = HorizonColour() + (zenith - HorizonColour()) * std::sqrt(elevation);
  if (d.z() > 0.02f) {  // clouds on a plane 1 km up, seen from below
    const float s = 1.0f / d.z();
    const float cloud = Fbm(d.x() * s, d.y() * s, 0.6f, 4, 0, 61);
    const float cover = Smoothstep(0.5f, 0.75f, cloud);
    c += (Colour(0.85f, 0.86f, 0.88f) - c) * cover;
  }
  return c;
}

}  // namespace littermap::sim
