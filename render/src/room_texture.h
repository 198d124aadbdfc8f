// Internal: the room's projective texture (ProjectedAlbedo) as the path tracer reads it at every
// room hit. ProjectedAlbedo keeps a pixel's first surface, albedo, photo radiance and whether
// that radiance is usable in four arrays, so a bounce landing on the room touched three or four
// cache lines in different places of memory. Here what every room hit reads (the surface, to
// test the projection) and what a bounce that ends on the photo reads (its radiance) sit in one
// 16-byte record per pixel, and the albedo, read only where a path goes on from the room (camera
// hits, mostly: coherent), in a table of its own; the projection runs inline. Every answer is
// ProjectedAlbedo's to the bit (pixelShowing, albedoAtPixel, radianceAtPixel: the same
// arithmetic in the same order).
#pragma once

#include "inlay/render/scene.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace inlay::detail {

class RoomTexture {
 public:
  struct alignas(16) Texel {
    float radiance[3];  // photoRadiance.rgb() of the pixel
    // firstSurfacePerPixel (-1: none) + 1, shifted left by one; the low bit: radianceAtPixel()
    // would answer true.
    uint32_t surfaceAndUsable;
    int surface() const { return int(surfaceAndUsable >> 1) - 1; }
    bool radianceUsable() const { return surfaceAndUsable & 1u; }
  };
  static_assert(sizeof(Texel) == 16);

  RoomTexture() = default;
  explicit RoomTexture(const ProjectedAlbedo& pa) : surfaceMean_(pa.surfaceMean) {
    const int w = pa.albedo.width, h = pa.albedo.height;
    // pixelShowing()'s conditions for any answer at all.
    if (pa.albedo.empty() || pa.firstSurfacePerPixel.size() != size_t(w) * h || pa.camera.widthPx <= 0 ||
        pa.camera.heightPx <= 0)
      return;
    const ImageF& photo = pa.photoRadiance;
    const bool photoUsable = photo.channels >= 3 && photo.width == w && photo.height == h &&
                             pa.photoRadianceUsable.size() == size_t(w) * h;
    texels_.resize(size_t(w) * h);
    albedo_.resize(size_t(w) * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        Texel& t = texels_[i];
        const Vec3 a = pa.albedo.rgb(x, y);
        const Vec3 r = photoUsable ? photo.rgb(x, y) : Vec3(Vec3::Zero());
        for (int c = 0; c < 3; ++c) albedo_[i][size_t(c)] = float(a[c]), t.radiance[c] = float(r[c]);
        const bool usable = photoUsable && pa.photoRadianceUsable[i] && r.allFinite();
        // Surface ids are below 2^30 (a room has tens); a larger one would not fit.
        const int32_t surface = std::clamp(pa.firstSurfacePerPixel[i], -1, (1 << 30) - 2);
        t.surfaceAndUsable = (uint32_t(surface + 1) << 1) | (usable ? 1u : 0u);
      }
    cameraFromWorld_ = pa.camera.cameraFromWorld();
    centre_ = pa.camera.centreWorld();
    principal_ = pa.camera.principalPx;
    focal_ = pa.camera.focalPx;
    width_ = w, height_ = h;
    cameraWidth_ = pa.camera.widthPx, cameraHeight_ = pa.camera.heightPx;
  }

  // ProjectedAlbedo::pixelShowing() as its texel; null where that is nullopt.
  const Texel* texelShowing(int surfaceId, const Vec3& pointWorld) const {
    return shows(texelAt(pointWorld), surfaceId);
  }
  // The texel the camera sees pointWorld in, whatever surface it shows (null: outside the
  // photo or behind the camera); memory untouched, so that a caller can prefetch it.
  const Texel* texelAt(const Vec3& pointWorld) const {
    if (texels_.empty()) return nullptr;
    // Camera::project(), then pixelShowing()'s scaling and test.
    const Vec3 c = cameraFromWorld_ * (pointWorld - centre_);
    if (!(c.z() < -1e-12)) return nullptr;
    const double inv = 1.0 / -c.z();
    const double px = principal_.x() + focal_ * c.x() * inv, py = principal_.y() - focal_ * c.y() * inv;
    const double x = px * double(width_) / cameraWidth_, y = py * double(height_) / cameraHeight_;
    if (!(x >= 0 && y >= 0 && x < width_ && y < height_)) return nullptr;
    return &texels_[size_t(std::min(height_ - 1, int(y))) * width_ +
                    size_t(std::min(width_ - 1, int(x)))];
  }
  // texelAt()'s answer when it shows surface `surfaceId`, else null.
  static const Texel* shows(const Texel* t, int surfaceId) {
    return t && t->surface() == surfaceId ? t : nullptr;
  }
  // ProjectedAlbedo::albedoAtPixel().
  Vec3 albedo(int surfaceId, const Texel* t) const {
    if (t) {
      const std::array<float, 3>& a = albedo_[indexOf(t)];
      return Vec3(a[0], a[1], a[2]);
    }
    const bool haveMean = surfaceId >= 0 && size_t(surfaceId) < surfaceMean_.size();
    return haveMean ? surfaceMean_[size_t(surfaceId)] : Vec3(0.5, 0.5, 0.5);
  }
  // The grid (the albedo's pixels) and its records, by index y * width() + x.
  int width() const { return texels_.empty() ? 0 : width_; }
  int height() const { return texels_.empty() ? 0 : height_; }
  size_t texelCount() const { return texels_.size(); }
  const Texel& texel(size_t i) const { return texels_[i]; }
  // The index of a texel texelShowing() returned.
  size_t indexOf(const Texel* t) const { return size_t(t - texels_.data()); }
  // Asks the cache for what camera hits through a run of the frame's row read first: the texels
  // and albedo records of the grid's row at fraction fy of its height, from fraction fx0 to fx1
  // of its width (a frame's pixel centres; the camera sees the photo's frame). A hint: nothing is
  // read, and a point the filter's jitter moves to a neighbour just misses as before. Returns
  // the first and last index (indexOf) it asked for; {1, 0} when none.
  std::pair<size_t, size_t> prefetchRun(double fx0, double fx1, double fy) const {
    if (texels_.empty() || !(fy >= 0 && fy < 1) || !(fx0 >= 0 && fx0 <= fx1 && fx1 < 1)) return {1, 0};
    const size_t row = size_t(std::min(height_ - 1, int(fy * height_))) * size_t(width_);
    const size_t first = row + size_t(std::min(width_ - 1, int(fx0 * width_)));
    const size_t last = row + size_t(std::min(width_ - 1, int(fx1 * width_)));
    prefetchLines(&texels_[first], &texels_[last]);
    prefetchLines(&albedo_[first], &albedo_[last]);
    return {first, last};
  }
  // ProjectedAlbedo::radianceAtPixel().
  static bool radiance(const Texel* t, Vec3* radiance) {
    if (!t || !t->radianceUsable()) return false;
    *radiance = Vec3(t->radiance[0], t->radiance[1], t->radiance[2]).cwiseMax(0.0);
    return true;
  }

 private:
  // Every cache line from the one holding `first` to the one holding `last`.
  template <class T>
  static void prefetchLines(const T* first, const T* last) {
    constexpr uintptr_t kLine = 64;
    const uintptr_t end = reinterpret_cast<uintptr_t>(last + 1);
    for (uintptr_t a = reinterpret_cast<uintptr_t>(first) & ~(kLine - 1); a < end; a += kLine)
      __builtin_prefetch(reinterpret_cast<const void*>(a));
  }

  std::vector<Texel> texels_;  // albedo.width x albedo.height; empty: no pixel shows anything
  std::vector<std::array<float, 3>> albedo_;  // albedo.rgb() of the pixels, as texels_
  std::vector<Vec3> surfaceMean_;
  Mat3 cameraFromWorld_ = Mat3::Identity();
  Vec3 centre_ = Vec3::Zero();
  Vec2 principal_ = Vec2::Zero();
  double focal_ = 1;
  int width_ = 0, height_ = 0, cameraWidth_ = 1, cameraHeight_ = 1;
};

}  // namespace inlay::detail
