#pragma once
// Wear that makes litter hard to see (LitterSpec's dirty_fraction, crushed_fraction,
// clear_bottle_fraction, on_gravel_fraction): what happened to one item, drawn from the litter's
// own wear stream, then applied to the item's primitive. The renderer turns `dirt` and
// `transmission` into colours (sim/object_shading.cpp, sim/colour_image.cpp).

#include <string>

#include "sim/random.hpp"
#include "sim/world.hpp"

namespace littermap::sim {

struct LitterWear {
  bool on_gravel = false;   // dropped on a gravel patch rather than where litter gathers
  double dirt = 0;          // 0 clean .. 1 caked in wet soil
  double crushed_to = 1;    // share of a can's height (standing) or diameter (lying) left
  double transmission = 0;  // clear bottle: share of the light from behind passing through
};

// The wear of one item of class `label`. Always takes the same number of draws from `rng`, so
// each share changes only the items it picks and the draws of later items stay put.
LitterWear DrawLitterWear(const LitterSpec& spec, const std::string& label, Rng& rng);

// Applies `wear` to a litter primitive placed as made (size, colour and pose drawn, not yet
// lifted onto the ground): a crushed can's size, a clear bottle's colour, dirt.
void ApplyLitterWear(const LitterWear& wear, WorldObject& object);

}  // namespace littermap::sim
