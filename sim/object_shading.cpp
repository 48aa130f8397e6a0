// Object surfaces of the simulated camera (declared in sim/surface_shading.hpp): the object's
// colour_rgb modulated by a pattern of its texture family in object coordinates, plus a
// highlight for shiny materials (cans, bottles, metal).

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "sim/procedural_noise.hpp"
#include "sim/surface_shading.hpp"

namespace littermap::sim {
namespace {

using Colour = Eigen::Vector3f;

float Fade(float footprint_m, float feature_m) {
  return std::clamp(1.5f - footprint_m / feature_m, 0.0f, 1.0f);
}

// Brightness factor 1 ± contrast from value noise at `frequency` cycles per metre.
float Grain(float a, float b, float frequency, float contrast, float fp, std::uint32_t salt) {
  return 1.0f + 2.0f * contrast *
                    (FilteredNoise(a * frequency, b * frequency, fp * frequency, salt) - 0.5f);
}

// Printed packaging: a few colour blocks per face (brand colour, white, dark text bands).
Colour Printed(const ObjectSurface& o, const Eigen::Vector3f& q, float fp) {
  const Eigen::Vector3f t = q.cwiseQuotient(o.size_m) + Eigen::Vector3f::Constant(0.5f);
  const auto cell = [&](float v, int n) { return static_cast<std::uint64_t>(v * float(n)); };
  const std::uint64_t h = Hash3(cell(t.x(), 3), cell(t.y(), 2) * 7 + cell(t.z(), 2), o.salt);
  const float u = HashToUnit(h);
  Colour c = o.colour_rgb;
  if (u < 0.2f)
    c = Colour(0.85f, 0.85f, 0.82f);
  else if (u < 0.32f)
    c = Colour(0.7f, 0.08f, 0.06f);
  else if (u < 0.42f)
    c = Colour(0.05f, 0.1f, 0.45f);
  else if (u < 0.52f)
    c = Colour(0.05f, 0.05f, 0.05f);
  const float mix = Fade(fp, 0.3f * o.size_m.minCoeff() + 0.01f);
  return o.colour_rgb + (c - o.colour_rgb) * mix;
}

// Park structure: trees, bushes, rocks, benches, bins, fences.
SurfaceSample StructureSample(const ObjectSurface& o, const Eigen::Vector3f& q, float fp) {
  const Colour& base = o.colour_rgb;
  switch (o.texture) {
    case SurfaceTexture::kBark: {  // vertical grooves
      const float around = std::atan2(q.y(), q.x()) * 0.5f * o.size_m.x();
      return {base * Grain(around * 6, q.z() * 0.4f, 4, 0.45f, fp, 71) *
              Grain(q.x() + q.y(), q.z(), 60, 0.15f, fp, 72)};
    }
    case SurfaceTexture::kLeaves: {  // clumps of lit and shaded foliage
      const float n = Fbm(q.x() + 0.6f * q.z(), q.y() - 0.8f * q.z(), 5, 3, fp, 73);
      const float b = 0.35f + 1.3f * n;
      return {base.cwiseProduct(Colour(b * (0.8f + 0.4f * n), b, b * 0.8f))};
    }
    case SurfaceTexture::kStone:
      return {base * Grain(q.x() + q.z(), q.y(), 8, 0.15f, fp, 74) *
              Grain(q.x() - q.z(), q.y() + q.z(), 70, 0.2f, fp, 75)};
    case SurfaceTexture::kWood: {  // grain along the longest axis
      const bool along_x = o.size_m.x() >= o.size_m.y();
      const float along = along_x ? q.x() : q.y(), across = (along_x ? q.y() : q.x()) + q.z();
      return {base * Grain(across * 40, along * 1.5f, 1, 0.2f, fp * 40, 76)};
    }
    case SurfaceTexture::kMetal:
      return {base * Grain(q.x(), q.y() + q.z(), 20, 0.08f, fp, 77), 0.35f, 25};
    default:
      break;
  }
  return {base * Grain(q.x() + q.z(), q.y(), 10, 0.1f, fp, 83)};
}

// Litter and its natural look-alikes.
SurfaceSample SmallObjectSample(const ObjectSurface& o, const Eigen::Vector3f& q, float fp) {
  const Colour& base = o.colour_rgb;
  const float half_z = 0.5f * o.size_m.z();
  switch (o.texture) {
    case SurfaceTexture::kAluminium: {  // silver rims above and below the print
      const bool rim = std::abs(q.z()) > 0.8f * half_z;
      return {rim ? Colour(0.7f, 0.7f, 0.72f) : base, 0.7f, 40};
    }
    case SurfaceTexture::kPlastic: {  // bottle with a cap; a clear bottle's is small and opaque
      const bool cap = q.z() > 0.85f * half_z &&
                       (o.transmission == 0 || q.head<2>().norm() < 0.2f * o.size_m.x());
      return {cap ? Colour(0.8f, 0.8f, 0.8f) : base, 0.6f, 60, cap ? 0.0f : o.transmission};
    }
    case SurfaceTexture::kPaper:
      return {base * Grain(q.x(), q.y() + q.z(), 150, 0.05f, fp, 78)};
    case SurfaceTexture::kCardboard:
      return {Printed(o, q, fp), 0.05f, 8};
    case SurfaceTexture::kStyrofoam:
      return {base * Grain(q.x() + q.z(), q.y(), 200, 0.06f, fp, 79)};
    case SurfaceTexture::kPlasticFilm: {  // crumpled: creases catch and lose the light
      const float crease = Fbm(q.x(), q.y(), 25, 2, fp, 80);
      return {base * (0.45f + 1.1f * crease), 0.4f, 15};
    }
    case SurfaceTexture::kPetals: {  // a yellow heart in the flower
      const float r = q.head<2>().norm() / (0.5f * o.size_m.x());
      return {r < 0.3f ? Colour(0.85f, 0.6f, 0.05f) : base};
    }
    case SurfaceTexture::kLeaf: {  // darker midrib, mottled blade
      const float rib = std::abs(q.y()) < 0.06f * o.size_m.y() ? 0.75f : 1.0f;
      return {base * rib * Grain(q.x(), q.y(), 60, 0.2f, fp, 81)};
    }
    case SurfaceTexture::kCone: {  // overlapping scales
      const float scales = ValueNoise(std::atan2(q.y(), q.x()) * 2.5f, q.z() * 120, 82);
      return {base * (0.55f + 0.7f * scales * Fade(fp, 0.008f) + 0.35f * (1 - Fade(fp, 0.008f)))};
    }
    case SurfaceTexture::kMushroom: {  // white warts on red caps
      const std::uint64_t h = Hash3(std::uint64_t(std::floor(q.x() / 0.012f) + 1000),
                                    std::uint64_t(std::floor(q.y() / 0.012f) + 1000), o.salt);
      const bool spot = base.x() > 2 * base.y() && q.z() > 0 && HashToUnit(h) < 0.25f;
      return {spot ? Colour(0.9f, 0.88f, 0.8f) : base, 0.2f, 10};
    }
    default:
      break;
  }
  return {base * Grain(q.x() + q.z(), q.y(), 10, 0.1f, fp, 83)};
}

// Wet soil on an item (dirt 0..1): wet surfaces darken (water fills the pores), a film of mud
// greys the print, and smears of mud cover about half of it in blotches of a few cm, browner
// the dirtier it is; mud is matt.
void Soil(const ObjectSurface& o, const Eigen::Vector3f& q, float fp, SurfaceSample& s) {
  const Colour mud(0.12f, 0.085f, 0.05f);  // wet soil: half as bright as dry (0.2-0.3)
  const float grey = s.albedo.dot(Colour(0.2126f, 0.7152f, 0.0722f));
  Colour c = s.albedo + (Colour::Constant(grey) - s.albedo) * (0.5f * o.dirt);
  c *= 1 - 0.5f * o.dirt;
  const float shift = float(o.salt % 1024u);  // each item its own blotches
  const float blotch = Fbm(q.x() + 0.4f * q.z() + shift, q.y() - 0.4f * q.z(), 18, 2, fp, 84);
  const float t = std::clamp((blotch - 0.35f) / 0.3f, 0.0f, 1.0f);
  const float cover = o.dirt * t * t * (3 - 2 * t);
  s.albedo = c + (mud - c) * cover;
  s.specular *= 1 - 0.7f * o.dirt;
  s.transmission *= 1 - cover;  // mud on clear plastic is opaque
}

}  // namespace

SurfaceTexture SurfaceTextureFromName(const std::string& name) {
  static const std::array<std::pair<const char*, SurfaceTexture>, 15> kNames = {{
      {"bark", SurfaceTexture::kBark},
      {"leaves", SurfaceTexture::kLeaves},
      {"stone", SurfaceTexture::kStone},
      {"wood", SurfaceTexture::kWood},
      {"metal", SurfaceTexture::kMetal},
      {"aluminium", SurfaceTexture::kAluminium},
      {"plastic", SurfaceTexture::kPlastic},
      {"paper", SurfaceTexture::kPaper},
      {"cardboard", SurfaceTexture::kCardboard},
      {"styrofoam", SurfaceTexture::kStyrofoam},
      {"plastic_film", SurfaceTexture::kPlasticFilm},
      {"petals", SurfaceTexture::kPetals},
      {"leaf", SurfaceTexture::kLeaf},
      {"cone", SurfaceTexture::kCone},
      {"mushroom", SurfaceTexture::kMushroom},
  }};
  for (const auto& [key, texture] : kNames) {
    if (name == key) return texture;
  }
  return SurfaceTexture::kPlain;
}

std::vector<ObjectSurface> MakeObjectSurfaces(const World& world) {
  std::vector<ObjectSurface> surfaces;
  surfaces.reserve(world.objects.size());
  for (const WorldObject& object : world.objects) {
    ObjectSurface s;
    s.texture = SurfaceTextureFromName(object.texture);
    s.R_object_world = RotationFromRpy(object.orientation).transpose().cast<float>();
    s.center_m = object.center_m.cast<float>();
    s.size_m = object.size_m.cast<float>();
    s.colour_rgb = object.colour_rgb.cast<float>();
    s.ground_z_m = static_cast<float>(world.terrain.HeightAt(object.center_m.head<2>()));
    s.salt = static_cast<std::uint32_t>(HashMix(static_cast<std::uint64_t>(object.id) + 17));
    s.dirt = static_cast<float>(object.dirt);
    s.transmission = static_cast<float>(object.transmission);
    surfaces.push_back(s);
  }
  return surfaces;
}

SurfaceSample ShadeObject(const ObjectSurface& object, const Eigen::Vector3f& p_world,
                          float footprint_m) {
  const Eigen::Vector3f q = object.R_object_world * (p_world - object.center_m);
  SurfaceSample s = object.texture >= SurfaceTexture::kAluminium
                        ? SmallObjectSample(object, q, footprint_m)
                        : StructureSample(object, q, footprint_m);
  if (object.dirt > 0) Soil(object, q, footprint_m, s);
  s.albedo = s.albedo.cwiseMax(0.0f).cwiseMin(1.0f);
  return s;
}

}  // namespace littermap::sim
