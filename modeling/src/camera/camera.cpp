#include "inlay/modeling/camera.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <vector>

namespace inlay {

namespace {

// Scale a pixel position to a unit-norm homogeneous point (x, y, w) so that a far-away
// vanishing point (1e7 px) is an ordinary direction with w near 0.
Vec3 homogeneous(const Vec2& p) {
  Vec3 h(p.x(), p.y(), 1.0);
  return h / h.norm();
}

// Direction (OpenCV camera frame: x right, y down, z forward) of a homogeneous image point.
Vec3 rayDirectionCv(const Vec3& h, double focalPx, const Vec2& principalPx) {
  Vec3 d((h.x() - principalPx.x() * h.z()) / focalPx, (h.y() - principalPx.y() * h.z()) / focalPx,
         h.z());
  return d.normalized();
}

bool finiteVec(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

}  // namespace

Vec3 Camera::directionThroughPixel(const Vec2& px) const {
  const Vec3 dCamera((px.x() - principalPx.x()) / focalPx, -(px.y() - principalPx.y()) / focalPx, -1.0);
  return (worldFromCamera * dCamera).normalized();
}

std::optional<Vec2> Camera::project(const Vec3& world) const {
  const Vec3 c = cameraFromWorld() * (world - centreWorld());
  if (!(c.z() < -1e-12)) return std::nullopt;
  const double inv = 1.0 / -c.z();
  return Vec2(principalPx.x() + focalPx * c.x() * inv, principalPx.y() - focalPx * c.y() * inv);
}

double Camera::depthOf(const Vec3& world) const {
  return -(cameraFromWorld() * (world - centreWorld())).z();
}

Vec3 Camera::vanishingPointOf(const Vec3& directionWorld) const {
  const Vec3 c = cameraFromWorld() * directionWorld;
  // x = cx + f cx/(-cz), y = cy - f cy/(-cz), as a homogeneous point with w = -cz.
  Vec3 h(principalPx.x() * -c.z() + focalPx * c.x(), principalPx.y() * -c.z() - focalPx * c.y(), -c.z());
  const double n = h.norm();
  return n > 0 ? Vec3(h / n) : h;
}

double Camera::horizontalFovDeg() const {
  return 2.0 * std::atan(0.5 * widthPx / focalPx) * 180.0 / M_PI;
}

Camera levelCamera(int widthPx, int heightPx, double focalPx, double heightM) {
  Camera cam;
  cam.widthPx = widthPx;
  cam.heightPx = heightPx;
  cam.focalPx = focalPx;
  cam.principalPx = Vec2(0.5 * widthPx, 0.5 * heightPx);
  cam.worldFromCamera = Mat3::Identity();
  cam.heightM = heightM;
  return cam;
}

Expected<Camera> cameraFromVanishingPoints(const VanishingInput& in) {
  const std::string key = "camera.vanishing_points_px";
  if (in.widthPx <= 0 || in.heightPx <= 0) return Error{"", "photo", "the image has no pixels"};
  for (int i = 0; i < 3; ++i)
    if (!finiteVec(in.vanishingPointsPx[i]))
      return Error{"", key + "[" + std::to_string(i) + "]", "is not a finite number"};
  if (in.focalPx && !(std::isfinite(*in.focalPx) && *in.focalPx > 0))
    return Error{"", "camera.focal_px", "must be a positive finite number"};
  if (in.principalPx && !finiteVec(*in.principalPx))
    return Error{"", "camera.principal_px", "is not a finite number"};

  Camera cam;
  cam.widthPx = in.widthPx;
  cam.heightPx = in.heightPx;
  cam.heightM = in.heightM;
  cam.principalPx = in.principalPx ? *in.principalPx : Vec2(0.5 * in.widthPx, 0.5 * in.heightPx);

  Vec3 h[3];
  for (int i = 0; i < 3; ++i) h[i] = homogeneous(in.vanishingPointsPx[i]);

  if (in.focalPx) {
    cam.focalPx = *in.focalPx;
  } else {
    // Orthogonality of two back-projected directions: (K^-1 vi) . (K^-1 vj) = 0 gives
    // f^2 = -[(ai - cx wi)(aj - cx wj) + (bi - cy wi)(bj - cy wj)] / (wi wj).
    // Pairs with a vanishing point near infinity (w ~ 0) say nothing about f: weight by |wi wj|.
    const double cx = cam.principalPx.x(), cy = cam.principalPx.y();
    const double diag = std::hypot(double(in.widthPx), double(in.heightPx));
    double sumW = 0, sumF = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j) {
        const double wiwj = h[i].z() * h[j].z();
        // |w| of a point at distance r from the origin is about 1/r: ignore pairs with a point
        // more than 1e4 image diagonals away (numerically at infinity for this purpose).
        const double wMin = 1.0 / (1e4 * diag);
        if (std::abs(h[i].z()) < wMin || std::abs(h[j].z()) < wMin) continue;
        const double num = (h[i].x() - cx * h[i].z()) * (h[j].x() - cx * h[j].z()) +
                           (h[i].y() - cy * h[i].z()) * (h[j].y() - cy * h[j].z());
        const double f2 = -num / wiwj;
        if (!(f2 > 0) || !std::isfinite(f2)) continue;
        const double w = std::abs(wiwj);
        sumW += w;
        sumF += w * std::sqrt(f2);
      }
    if (!(sumW > 0))
      return Error{"", key,
                   "cannot give a focal length (fewer than two finite vanishing points, or they "
                   "are not of orthogonal directions for this principal point); give "
                   "camera.focal_px"};
    cam.focalPx = sumF / sumW;
  }
  if (!(cam.focalPx > 1e-3 && cam.focalPx < 1e7))
    return Error{"", "camera.focal_px", "the focal length is out of range"};

  // Columns: the world axes in the OpenGL camera frame (x right, y up, looking down -z).
  Mat3 cameraFromWorld;
  for (int i = 0; i < 3; ++i) {
    const Vec3 dCv = rayDirectionCv(h[i], cam.focalPx, cam.principalPx);
    Vec3 dGl(dCv.x(), -dCv.y(), -dCv.z());
    // Signs: world x runs to the right (+x_cam), world y up (+y_cam), and the camera looks
    // toward world -z, so world +z points backward (+z_cam).
    const double s = dGl[i];
    if (s < 0) dGl = -dGl;
    cameraFromWorld.col(i) = dGl;
  }
  // Nearest rotation (orthogonal Procrustes); a reflection means the z sign was ambiguous.
  Eigen::JacobiSVD<Mat3> svd(cameraFromWorld, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 r = svd.matrixU() * svd.matrixV().transpose();
  if (r.determinant() < 0) {
    cameraFromWorld.col(2) = cameraFromWorld.col(0).cross(cameraFromWorld.col(1));
    Eigen::JacobiSVD<Mat3> svd2(cameraFromWorld, Eigen::ComputeFullU | Eigen::ComputeFullV);
    r = svd2.matrixU() * svd2.matrixV().transpose();
  }
  if (!r.allFinite() || std::abs(r.determinant() - 1.0) > 1e-6)
    return Error{"", key, "the three vanishing points do not give a rotation"};
  // Three directions that are far from orthogonal after the focal length: a wrong order or a
  // wrong point. Accept up to about 10 degrees of disagreement.
  for (int i = 0; i < 3; ++i)
    if (cameraFromWorld.col(i).normalized().dot(r.col(i)) < std::cos(10.0 * M_PI / 180.0))
      return Error{"", key,
                   "the vanishing points are not of three orthogonal directions (axis " +
                       std::string(1, "xyz"[i]) + " is off by more than 10 degrees)"};
  cam.worldFromCamera = r.transpose();
  return cam;
}

}  // namespace inlay
