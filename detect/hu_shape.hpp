#pragma once
// Shape by Hu moments (thesis 3.2): the seven invariants of Hu (1962) of an object's binary mask
// are invariant to translation, rotation and scale; the thesis drops the third, which is not
// independent of the others (Flusser 2000), and keeps six. The thesis's distance between two
// shapes A and B is
//   D(A, B) = sum_i |1 / m_Ai - 1 / m_Bi|      over the six invariants (HuInverseDistance).
//
// The raw reciprocals are numerically treacherous: centrally symmetric shapes (cans, bottles,
// boxes, plates: the litter the thesis wants to find) have invariants 3..7 exactly zero in theory
// and only rasterisation noise (1e-28 .. 1e-7 for 20..400 px rectangles, ellipses and circles,
// measured with OpenCV 4.6), and a circle has I2 = 0 too. 1 / noise is an arbitrary number of
// order 1e7 .. 1e28 that would decide the distance alone. So an invariant with magnitude below
// HuDistanceOptions::zero_threshold counts as zero, and a zero counts as +zero_threshold in the
// reciprocal: two zeros agree (term 0), and a zero against a real value costs at most
// 1 / zero_threshold. Even so the sum is dominated by the smallest invariants above the
// threshold, whose reciprocals are largest.
//
// HuLogDistance is the usable alternative: each invariant mapped by the signed logarithm
//   s(m) = sign(m) log10(1 + |m| / zero_threshold)
// (zero at zero, continuous through it, about log10 |m| plus a constant for |m| well above the
// threshold) and D = sum_i |s(m_Ai) - s(m_Bi)|. It follows OpenCV's matchShapes, which uses
// sign(m) log10 |m|, but OpenCV's I1 takes reciprocals of those logs, which blow up where |m| is
// near 1 (I1 of a 12:1 stick) and whose sign flips with noise around zero; the difference of
// signed logs (OpenCV's I2 form) with the threshold has neither problem.

#include <array>

#include <opencv2/core.hpp>

namespace littermap::detect {

inline constexpr int kHuShapeValueCount = 6;

struct HuShape {
  // Hu's invariants I1, I2, I4, I5, I6, I7 (cv::HuMoments indices 0, 1, 3, 4, 5, 6).
  std::array<double, kHuShapeValueCount> values{};
  double area_px = 0;  // m00: the object's pixel count
};

// Hu moments of a CV_8UC1 mask (non-zero = object) via cv::moments(binaryImage = true) and
// cv::HuMoments. Throws UsageError for another type or a mask without object pixels.
HuShape ComputeHuShape(const cv::Mat& mask);

struct HuDistanceOptions {
  // Invariants of smaller magnitude count as zero. Symmetric shapes of 20 px and more showed
  // noise up to 1e-6 in I3/I4 (a 20 px circle) and far less in the others; an asymmetric
  // triangle's I4 is about 5e-5, so 1e-6 separates noise from shape down to small objects.
  double zero_threshold = 1e-6;
  void Validate() const;
};

// The thesis's sum_i |1/m_Ai - 1/m_Bi| with the zero handling above. Throws UsageError for a
// non-positive threshold.
double HuInverseDistance(const HuShape& a, const HuShape& b, const HuDistanceOptions& options = {});

// sum_i |s(m_Ai) - s(m_Bi)| with the signed logarithm above.
double HuLogDistance(const HuShape& a, const HuShape& b, const HuDistanceOptions& options = {});

}  // namespace littermap::detect
