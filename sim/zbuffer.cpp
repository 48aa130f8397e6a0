#include "sim/zbuffer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace littermap::sim {
namespace {

RasterVertex Lerp(const RasterVertex& a, const RasterVertex& b, float t) {
  return {a.p_camera + t * (b.p_camera - a.p_camera), a.n_camera + t * (b.n_camera - a.n_camera)};
}

// The pixel centres [first, last] within [0, size) spanned by three screen coordinates (widened by
// the 0.01 px edge tolerance below); false when none.
bool PixelRange(const float (&s)[3], int size, int& first, int& last) {
  const float low = std::min({s[0], s[1], s[2]}) - 0.01f;
  const float high = std::max({s[0], s[1], s[2]}) + 0.01f;
  if (!(high >= 0 && low <= float(size - 1))) return false;  // also rejects NaN
  first = std::max(0, static_cast<int>(std::ceil(low)));
  last = std::min(size - 1, static_cast<int>(std::floor(high)));
  return first <= last;
}

}  // namespace

ZBuffer::ZBuffer(const PinholeCamera& camera, float near_m, float far_m)
    : fx_(static_cast<float>(camera.fx)),
      fy_(static_cast<float>(camera.fy)),
      cx_(static_cast<float>(camera.cx)),
      cy_(static_cast<float>(camera.cy)),
      width_(camera.width),
      height_(camera.height),
      near_m_(near_m),
      far_m_(far_m) {
  const std::size_t n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  depth_m_.resize(n);
  ids_.resize(n);
  normals_.resize(n);
  Clear();
}

void ZBuffer::Clear() {
  std::fill(depth_m_.begin(), depth_m_.end(), std::numeric_limits<float>::infinity());
  std::fill(ids_.begin(), ids_.end(), kSkyInstance);
  std::fill(normals_.begin(), normals_.end(), Eigen::Vector3f::Zero());
  triangles_drawn_ = 0;
}

void ZBuffer::DrawTriangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                           std::int32_t id) {
  const float za = a.p_camera.z(), zb = b.p_camera.z(), zc = c.p_camera.z();
  if (za < near_m_ && zb < near_m_ && zc < near_m_) return;
  if (za > far_m_ && zb > far_m_ && zc > far_m_) return;
  const Eigen::Vector3f centre = (a.p_camera + b.p_camera + c.p_camera) / 3;
  if (centre.dot(a.n_camera + b.n_camera + c.n_camera) > 0) return;  // back face
  if (za >= near_m_ && zb >= near_m_ && zc >= near_m_) {
    Fill(a, b, c, id);
    return;
  }
  // Sutherland–Hodgman against the plane z = near: a triangle becomes one or two triangles.
  const RasterVertex* in[3] = {&a, &b, &c};
  RasterVertex out[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const RasterVertex& p = *in[i];
    const RasterVertex& q = *in[(i + 1) % 3];
    const bool p_in = p.p_camera.z() >= near_m_, q_in = q.p_camera.z() >= near_m_;
    if (p_in) out[n++] = p;
    if (p_in != q_in) {
      out[n++] = Lerp(p, q, (near_m_ - p.p_camera.z()) / (q.p_camera.z() - p.p_camera.z()));
    }
  }
  for (int i = 1; i + 1 < n; ++i) Fill(out[0], out[i], out[i + 1], id);
}

// Edge-function rasterisation over the clipped bounding box; pixel centres at integer (u, v).
void ZBuffer::Fill(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                   std::int32_t id) {
  const RasterVertex* v[3] = {&a, &b, &c};
  float sx[3], sy[3], inv_z[3];
  for (int i = 0; i < 3; ++i) {
    inv_z[i] = 1.0f / v[i]->p_camera.z();
    sx[i] = fx_ * v[i]->p_camera.x() * inv_z[i] + cx_;
    sy[i] = fy_ * v[i]->p_camera.y() * inv_z[i] + cy_;
  }
  float area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
  if (std::abs(area) < 1e-12f) return;
  const float sign = area > 0 ? 1.0f : -1.0f;
  area *= sign;
  int x0, x1, y0, y1;
  if (!PixelRange(sx, width_, x0, x1) || !PixelRange(sy, height_, y0, y1)) return;
  ++triangles_drawn_;
  // Edge i is opposite vertex i: w_i(x, y) = A_i x + B_i y + C_i, positive inside.
  // Pixels up to 0.01 px outside an edge count as inside: rounding must never leave a pixel on
  // a shared edge uncovered by both triangles (a crack); the overlap is resolved by the z-test.
  float ea[3], eb[3], ec[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    ea[i] = sign * (sy[j] - sy[k]);
    eb[i] = sign * (sx[k] - sx[j]);
    ec[i] = sign * (sx[j] * sy[k] - sx[k] * sy[j]) + 0.01f * std::hypot(ea[i], eb[i]);
  }
  const Eigen::Vector3f na = a.n_camera * inv_z[0], nb = b.n_camera * inv_z[1],
                        nc = c.n_camera * inv_z[2];
  for (int y = y0; y <= y1; ++y) {
    const float fy = static_cast<float>(y), fx0 = static_cast<float>(x0);
    float w0 = ea[0] * fx0 + eb[0] * fy + ec[0];
    float w1 = ea[1] * fx0 + eb[1] * fy + ec[1];
    float w2 = ea[2] * fx0 + eb[2] * fy + ec[2];
    const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
    for (int x = x0; x <= x1; ++x, w0 += ea[0], w1 += ea[1], w2 += ea[2]) {
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const float norm = 1.0f / (w0 + w1 + w2);  // not 1/area: the edges were widened
      const float b0 = w0 * norm, b1 = w1 * norm, b2 = w2 * norm;
      const float iz = b0 * inv_z[0] + b1 * inv_z[1] + b2 * inv_z[2];
      const float z = 1.0f / iz;
      const std::size_t i = row + static_cast<std::size_t>(x);
      if (z >= depth_m_[i] || z > far_m_ || z < near_m_) continue;
      depth_m_[i] = z;
      ids_[i] = id;
      normals_[i] = (b0 * na + b1 * nb + b2 * nc) * z;
    }
  }
}

}  // namespace littermap::sim
