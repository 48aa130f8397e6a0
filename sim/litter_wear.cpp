#include "sim/litter_wear.hpp"

#include <cmath>
#include <numbers>

namespace littermap::sim {

LitterWear DrawLitterWear(const LitterSpec& spec, const std::string& label, Rng& rng) {
  // Seven draws per item whatever the shares and the class (see the header).
  const double u_gravel = rng.Uniform01(), u_dirty = rng.Uniform01(), dirt = rng.Uniform(0.5, 1);
  const double u_crushed = rng.Uniform01(), crushed_to = rng.Uniform(0.2, 0.4);
  const double u_clear = rng.Uniform01(), transmission = rng.Uniform(0.75, 0.9);
  LitterWear wear;
  wear.on_gravel = u_gravel < spec.on_gravel_fraction;
  if (u_dirty < spec.dirty_fraction) wear.dirt = dirt;
  if (label == "can" && u_crushed < spec.crushed_fraction) wear.crushed_to = crushed_to;
  if (label == "bottle" && u_clear < spec.clear_bottle_fraction) wear.transmission = transmission;
  return wear;
}

void ApplyLitterWear(const LitterWear& wear, WorldObject& object) {
  object.dirt = wear.dirt;
  if (wear.transmission > 0) {
    // Clear PET: a faint bluish-white of its own (Fresnel reflection), the rest shows what lies
    // behind it.
    object.transmission = wear.transmission;
    object.colour_rgb = {0.8, 0.85, 0.9};
  }
  if (wear.crushed_to < 1) {
    object.crushed = true;
    const double squeeze = 1 - wear.crushed_to;
    // Local z is the can's axis; lying, its local x points up (pitch π/2).
    const bool lying = std::abs(object.orientation.pitch_rad) > 0.25 * std::numbers::pi;
    if (lying) {
      // Flattened across: the section keeps about its perimeter, so the width grows towards
      // π/2 of the diameter as the height goes to nothing.
      object.size_m.x() *= wear.crushed_to;
      object.size_m.y() *= 1 + (std::numbers::pi / 2 - 1) * squeeze;
    } else {
      // Stepped on: the wall folds down and bulges a little.
      object.size_m.z() *= wear.crushed_to;
      object.size_m.x() *= 1 + 0.15 * squeeze;
      object.size_m.y() *= 1 + 0.15 * squeeze;
    }
  }
}

}  // namespace littermap::sim
