#pragma once
// What an object looks like, as numbers (thesis 3.2 plus the 3D cues depth gives): its nine
// colour bins, mean colour, brightness spread, shape moments and size. The thesis's distance
// features (naive Bayes, GMM energy, EMD and Hu distances to each class) are computed against a
// trained model in detect/litter_classifier.cpp.

#include <array>
#include <vector>

#include "detect/colour_bins.hpp"
#include "detect/hu_shape.hpp"
#include "detect/object_sample.hpp"

namespace littermap::detect {

struct ObjectDescription {
  ColourHistogram histogram;  // pixel counts per bin
  HuShape hu;                 // Hu moments without the 3rd
  std::vector<float> raw;     // the feature vector below
};

// raw = 9 bin shares, chroma (s cos h, s sin h), mean S, mean V, S and V spread, mean brightness
// gradient, fill ratio of the box, box aspect, size_m, width_m, height_m, height/size, 6
// log-scaled Hu moments.
inline constexpr int kRawFeatureCount = 9 + 7 + 2 + 4 + 6;

ObjectDescription DescribeObject(const ObjectSample& object);

}  // namespace littermap::detect
