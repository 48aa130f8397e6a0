#pragma once
// Reproducible random numbers for the simulator. std::mt19937_64 is fully specified by the
// standard, but std::uniform_real_distribution and std::normal_distribution are not, so the
// distributions are written out here: uniforms from the top 53 bits, normals by Box–Muller.
// Independent streams (world, litter, laser, odometry, ...) come from SplitMix64-mixed seeds, so
// adding draws to one stream never changes another.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace littermap::sim {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a well-mixed seed from (seed, stream).
inline std::uint64_t MixSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  Rng(std::uint64_t seed, std::uint64_t stream) : engine_(MixSeed(seed, stream)) {}

  // Uniform in [0, 1) with 53 random bits.
  double Uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double low, double high) { return low + (high - low) * Uniform01(); }
  // Uniform integer in [0, n); n > 0. The bias of the multiply is below 2^-53 * n.
  int Index(int n) { return static_cast<int>(Uniform01() * n); }
  bool Bernoulli(double p) { return Uniform01() < p; }
  // Standard normal by Box–Muller; both outputs of a pair are used.
  double Normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - Uniform01();  // (0, 1]: log is finite
    const double u2 = Uniform01();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2 * std::numbers::pi * u2);
    has_spare_ = true;
    return radius * std::cos(2 * std::numbers::pi * u2);
  }
  double Normal(double mean, double sigma) { return mean + sigma * Normal(); }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace littermap::sim
