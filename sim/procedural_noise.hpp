#pragma once
// Cheap deterministic noise for the renderer: integer hashes (no std distributions, whose output
// is implementation-defined), value noise on world coordinates so textures stay glued to the
// world as the camera moves, and a fast approximately-Gaussian draw for sensor noise.

#include <array>
#include <cmath>
#include <cstdint>

namespace littermap::sim {

// 64-bit finaliser of MurmurHash3 / SplitMix64: every input bit affects every output bit.
inline std::uint64_t HashMix(std::uint64_t x) {
  x ^= x >> 33;
  x *= 0xFF51AFD7ED558CCDull;
  x ^= x >> 33;
  x *= 0xC4CEB9FE1A85EC53ull;
  return x ^ (x >> 33);
}

inline std::uint64_t Hash3(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  return HashMix(a * 0x9E3779B97F4A7C15ull ^ HashMix(b + 0x632BE59BD9B4E019ull) ^
                 HashMix(c * 0x85157AF5ull + 0x7F4A7C15ull));
}

// Uniform in [0, 1) from the top 24 bits of a hash.
inline float HashToUnit(std::uint64_t h) {
  return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
}

// Approximately standard normal from one hash: the sum of four 16-bit uniforms (Irwin–Hall,
// variance 4/12) rescaled to unit variance. Tails end at ±3.46σ, which is fine for sensor noise
// and five times cheaper than Box–Muller.
inline float HashToNormal(std::uint64_t h) {
  const float sum =
      static_cast<float>((h & 0xFFFF) + ((h >> 16) & 0xFFFF) + ((h >> 32) & 0xFFFF) + (h >> 48)) *
      (1.0f / 65536.0f);
  return (sum - 2.0f) * 1.7320508f;
}

// 4096 standard-normal samples (zero mean, unit variance after normalisation), so one 64-bit
// hash gives several Gaussian draws by table lookup: a pixel's three colour-noise channels.
inline const std::array<float, 4096>& NormalTable() {
  static const std::array<float, 4096> table = [] {
    std::array<float, 4096> t{};
    double sum = 0, sum2 = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      t[i] = HashToNormal(HashMix(i + 0x7AB1E));
      sum += t[i];
    }
    const double mean = sum / double(t.size());
    for (float& v : t) sum2 += (v - mean) * (v - mean);
    const double scale = 1 / std::sqrt(sum2 / double(t.size()));
    for (float& v : t) v = static_cast<float>((v - mean) * scale);
    return t;
  }();
  return table;
}

// A well-mixed 64-bit hash of an integer lattice cell (one multiply–xorshift round).
inline std::uint64_t CellHash64(int ix, int iy, std::uint64_t salt) {
  return HashMix((static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32 |
                  static_cast<std::uint32_t>(iy)) ^
                 salt * 0x9E3779B97F4A7C15ull);
}

// floor() without a libm call (the build does not assume SSE4.1's roundss); |x| < 2^31.
inline int FastFloor(float x) {
  const int i = static_cast<int>(x);
  return x < static_cast<float>(i) ? i - 1 : i;
}

// Hash of an integer lattice point in 2D with a per-texture salt, in [0, 1). A 32-bit
// multiply–xorshift hash (Wellons' "lowbias32" constants): plenty for texture noise.
inline float LatticeValue(int ix, int iy, std::uint32_t salt) {
  std::uint32_t h = static_cast<std::uint32_t>(ix) * 0x8DA6B343u ^
                    static_cast<std::uint32_t>(iy) * 0xD8163841u ^ salt * 0xCB1AB31Fu;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// Smooth value noise in [0, 1) at (x, y) with unit lattice spacing (smoothstep interpolation).
inline float ValueNoise(float x, float y, std::uint32_t salt) {
  const int ix = FastFloor(x), iy = FastFloor(y);
  const float fx = static_cast<float>(ix), fy = static_cast<float>(iy);
  float tx = x - fx, ty = y - fy;
  tx = tx * tx * (3 - 2 * tx);
  ty = ty * ty * (3 - 2 * ty);
  const float a = LatticeValue(ix, iy, salt), b = LatticeValue(ix + 1, iy, salt);
  const float c = LatticeValue(ix, iy + 1, salt), d = LatticeValue(ix + 1, iy + 1, salt);
  return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

// Value noise whose contrast fades to its mean (0.5) once a pixel covers more than half a
// lattice cell: a cheap stand-in for mip-mapping that keeps fine textures from aliasing into
// sparkle far away. `footprint` is the pixel size in lattice units.
inline float FilteredNoise(float x, float y, float footprint, std::uint32_t salt) {
  const float fade = 1.0f - 2.0f * footprint;
  if (fade <= 0) return 0.5f;
  return 0.5f + (ValueNoise(x, y, salt) - 0.5f) * fade;
}

// Fractal sum of `octaves` octaves of filtered value noise at base frequency `scale` (cycles per
// unit), each octave doubling frequency and halving amplitude; result in [0, 1).
inline float Fbm(float x, float y, float scale, int octaves, float footprint, std::uint32_t salt) {
  float sum = 0, amplitude = 0.5f, norm = 0;
  for (int i = 0; i < octaves; ++i) {
    sum += amplitude * FilteredNoise(x * scale, y * scale, footprint * scale,
                                     salt + static_cast<std::uint32_t>(i) * 131u);
    norm += amplitude;
    amplitude *= 0.5f;
    scale *= 2;
  }
  return sum / norm;
}

}  // namespace littermap::sim
