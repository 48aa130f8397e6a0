#pragma once
// Earth Mover's Distance between two nine-bin colour histograms (thesis 3.2: "a true distance,
// usable for clustering"), computed by cv::EMD with the ground distances below. Both histograms
// are normalised to shares first, so the distance compares colour distributions, not object
// sizes, and lies in [0, 1].
//
// Ground distances between bins (ColourBinGroundDistances):
//  - two chromatic bins: the angle between their hue-interval centres on the hue circle, divided
//    by 180 degrees (0 = same hue, 1 = opposite hues). The centres are those of the thesis's
//    intervals, e.g. red [335, 371) -> 353 degrees, orange [11, 49) -> 30 degrees.
//  - black or white to any chromatic bin: 0.5. In the HSV cone the achromatic axis is the centre
//    of the hue circle, and a hue is as far from the centre (a radius) as half the distance to
//    its opposite hue (a diameter, 1).
//  - black to white: 1, the full length of the value axis, as different as opposite hues.
// With these values the ground distance is a metric (zero diagonal, symmetric, triangle
// inequality: arcs obey it, and any two bins are at most 1 = 0.5 + 0.5 apart via black or
// white), so the EMD over normalised histograms is a metric too (Rubner et al., IJCV 2000).

#include <opencv2/core.hpp>

#include "detect/colour_bins.hpp"

namespace littermap::detect {

inline constexpr double kAchromaticToChromaticDistance = 0.5;
inline constexpr double kBlackToWhiteDistance = 1.0;

// The 9 x 9 CV_32F ground distance matrix, rows and columns in ColourBin order.
cv::Mat ColourBinGroundDistances();

// EMD between the normalised histograms, in [0, 1]. Throws UsageError when either histogram is
// empty (no pixels: no distribution to compare) or has a negative or non-finite count.
double ColourEmd(const ColourHistogram& a, const ColourHistogram& b);

}  // namespace littermap::detect
