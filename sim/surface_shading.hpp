#pragma once
// Procedural surface colours for the simulated camera, all functions of world or object
// coordinates (never of pixels) so textures stay glued to the world as the camera moves. Colours
// are linear RGB albedos in 0..1; `footprint_m` is the size of one pixel on the surface and
// fades detail finer than a pixel to its mean instead of letting it alias.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sim/world.hpp"

namespace littermap::sim {

// Texture families of WorldObject::texture (unknown names render as kPlain). Park structure
// first, then from kAluminium on litter and natural look-alikes.
enum class SurfaceTexture : std::uint8_t {
  kPlain,
  kBark,
  kLeaves,
  kStone,
  kWood,
  kMetal,
  kAluminium,
  kPlastic,
  kPaper,
  kCardboard,
  kStyrofoam,
  kPlasticFilm,
  kPetals,
  kLeaf,
  kCone,
  kMushroom
};
SurfaceTexture SurfaceTextureFromName(const std::string& name);

// What shading needs of one object, resolved once per world.
struct ObjectSurface {
  SurfaceTexture texture = SurfaceTexture::kPlain;
  Eigen::Matrix3f R_object_world = Eigen::Matrix3f::Identity();
  Eigen::Vector3f center_m = Eigen::Vector3f::Zero();
  Eigen::Vector3f size_m = Eigen::Vector3f::Ones();
  Eigen::Vector3f colour_rgb = Eigen::Vector3f::Constant(0.5f);
  float ground_z_m = 0;    // terrain height under the centre
  std::uint32_t salt = 0;  // per-object pattern variation (print layout, spots)
  float dirt = 0;          // WorldObject::dirt
  float transmission = 0;  // WorldObject::transmission
};
std::vector<ObjectSurface> MakeObjectSurfaces(const World& world);

struct SurfaceSample {
  Eigen::Vector3f albedo = Eigen::Vector3f::Constant(0.5f);
  float specular = 0;   // strength of a white highlight ...
  float shininess = 1;  // ... with this Blinn–Phong exponent
  // Clear material: share of the light from behind the surface that passes through it (at
  // normal incidence); the renderer blends in what lies behind (sim/colour_image.cpp).
  float transmission = 0;
};

// Ground albedo of `type` at world (x, y).
Eigen::Vector3f GroundAlbedo(GroundType type, float x, float y, float footprint_m);
// The ground type lookup point, displaced by noise so region borders are ragged, not circles.
Eigen::Vector2f RaggedGroundPoint(float x, float y);

// Surface of `object` at world point p_world.
SurfaceSample ShadeObject(const ObjectSurface& object, const Eigen::Vector3f& p_world,
                          float footprint_m);

// Sky radiance (linear RGB) in world direction `d` (unit): a gradient from a pale horizon to a
// blue zenith with a few fair-weather clouds.
Eigen::Vector3f SkyColour(const Eigen::Vector3f& d);
// The haze colour distant ground fades into (aerial perspective).
Eigen::Vector3f HorizonColour();

}  // namespace littermap::sim
