// The pinhole camera of one photo.
//
// Frames: world (metres, y up, floor y = 0, camera centre at (0, heightM, 0), camera looking
// toward -z); camera (OpenGL convention: x right, y up, looking down -z); pixel (x right, y down,
// origin at the top-left corner of the top-left pixel). Square pixels, no skew, no distortion.
#pragma once

#include "inlay/modeling/core.h"

#include <array>
#include <optional>

namespace inlay {

struct Camera {
  int widthPx = 0;
  int heightPx = 0;
  double focalPx = 1.0;
  Vec2 principalPx{0, 0};
  Mat3 worldFromCamera = Mat3::Identity();  // rotation only
  double heightM = 1.6;

  Vec3 centreWorld() const { return Vec3(0, heightM, 0); }
  Mat3 cameraFromWorld() const { return worldFromCamera.transpose(); }
  // Unit direction (world) of the ray through a pixel position.
  Vec3 directionThroughPixel(const Vec2& px) const;
  Ray rayThroughPixel(const Vec2& px) const { return {centreWorld(), directionThroughPixel(px)}; }
  // Pixel position of a world point; nullopt when it is behind (or on) the camera plane.
  std::optional<Vec2> project(const Vec3& world) const;
  // Depth along the viewing axis (metres, > 0 in front).
  double depthOf(const Vec3& world) const;
  // Homogeneous image point (x, y, w) of a world direction (its vanishing point); unit norm.
  Vec3 vanishingPointOf(const Vec3& directionWorld) const;
  double horizontalFovDeg() const;
};

// Camera intrinsics and rotation from the three vanishing points of the world x, y, z axes.
// Vanishing points far away (parallel image lines) may be given as huge coordinates: the
// computation works on normalised homogeneous directions, so this is an ordinary case.
// `focalPx` / `principalPx`, when given, are taken as they are; otherwise the principal point
// is the image centre and the focal length comes from the finite orthogonal pairs.
// Errors: fewer than two finite vanishing points with no focal length given, an imaginary
// focal length (an obtuse vanishing triangle), or non-finite input.
struct VanishingInput {
  std::array<Vec2, 3> vanishingPointsPx;
  std::optional<double> focalPx;
  std::optional<Vec2> principalPx;
  int widthPx = 0;
  int heightPx = 0;
  double heightM = 1.6;
};
Expected<Camera> cameraFromVanishingPoints(const VanishingInput& input);

// A fallback camera with no structure: level, looking along -z, with the given horizontal field
// of view (or focal length) and the principal point at the centre.
Camera levelCamera(int widthPx, int heightPx, double focalPx, double heightM);

}  // namespace inlay
