// Camera and room from the photo alone: line segments, three orthogonal vanishing points, focal
// length and rotation, and the box layout (the back wall's four corners), each with how sure it
// is; and the correction the studio applies when the user fixes part of it.
//
// Pipeline (estimateCamera): the photo is reduced to grey at a working size (long side at most
// EstimateOptions::maxWorkingSidePx, area-averaged, so a 100 MP photo costs what a 1 MP one does),
// line segments are found (OpenCV FastLineDetector), a Manhattan triplet of directions is found
// by a hypothesis search on the Gaussian sphere over a ladder of focal lengths (three segments
// per hypothesis: two give one direction, the third the second one orthogonal to it), focal
// length and rotation are refined by robust least squares (Ceres) on the distance of each inlier
// segment's endpoints to the line through its midpoint and its vanishing point, and the back
// wall is found among rays through the vanishing points (edge support plus a line-based
// orientation map, after Hedau et al. 2009 and Lee et al. 2009).
//
// Frames and units: as in camera.h. Pixels are the photo's (x right, y down, origin at the
// top-left corner), whatever the working size was. Vanishing points are always also given as
// unit-norm homogeneous pixel points (x, y, w), w ~ 0 at infinity; `vanishingPointsPx` is the
// scene file's form (a huge coordinate, 1e7 px from the principal point, when w ~ 0).
//
// World axes: x is the horizontal room axis that runs most nearly left-to-right in the photo,
// y is up, z points back toward the camera (the camera looks toward -z); vanishing points and
// confidences come in the order x, y, z.
//
// Thread safety: the functions are pure (no shared state); several may run at once.
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"
#include "inlay/modeling/line_segment.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

namespace detail {
struct PhotoEdges;  // the photo's gradient at the layout's scale (layout.h)
}

// What is known about one vanishing point.
struct VanishingPointInfo {
  Vec3 homogeneousPx{0, 0, 1};      // unit norm (x, y, w); w ~ 0 at infinity
  Vec3 directionCamera{0, 0, -1};   // the world axis in the camera frame (OpenGL), unit
  bool atInfinity = false;          // farther than 1000 image diagonals from the centre
  std::vector<int> segmentIndices;  // its supporting segments: indices into CameraEstimate::
                                    // segments (their residualPx are the residuals)
  int segmentCount = 0;             // supporting segments (detected and user-given)
  double supportLengthPx = 0;       // their total length
  double rmsResidualPx = 0;         // root-mean-square endpoint residual of the supporters
  double angularSigmaDeg = 180;     // 1-sigma uncertainty of the direction from its own lines
  double confidence = 0;            // in [0, 1]: support beyond chance (a contrario, -log10 of
                                    // the expected false alarms) times precision of direction
  bool nearlyParallel = false;      // its lines are nearly parallel in the photo
};

struct EstimateTimings {
  double linesMs = 0;      // reduce to working size + line segments
  double vanishingMs = 0;  // hypothesis search
  double refineMs = 0;     // least squares, uncertainty
  double layoutMs = 0;     // back wall search
  double totalMs = 0;
};

// The hypothesis search's best score against time (STYLE: every iterative algorithm reports
// what it reached and when).
struct SearchProgress {
  double seconds = 0;
  double score = 0;  // length-weighted inlier score of the best Manhattan hypothesis so far
};

// The estimate. `camera` is always usable (finite, a rotation, focal > 0): when the photo shows
// no Manhattan structure it is the fallback (prior focal length, level or vertical-aligned
// rotation) and `manhattan` is false, the confidences are low and `warnings` say why.
struct CameraEstimate {
  Camera camera;                          // principal point: see principalSigma
  std::array<Vec2, 3> vanishingPointsPx;  // x, y, z: scene file form (huge when at infinity)
  std::array<VanishingPointInfo, 3> vanishingPoints;
  std::array<double, 3> confidence{0, 0, 0};  // = vanishingPoints[i].confidence
  double overallConfidence = 0;               // in [0, 1]: how far to trust camera rotation
  bool manhattan = false;                     // false: fallback camera, not measured
  double focalMinPx = 0, focalMaxPx = 0;      // about 95% interval (prior included)
  bool focalFromPrior = false;                // the photo did not determine the focal length
  // The principal point's 1-sigma per photo axis (px, posterior of the joint fit, prior
  // included) and whether the lines located it: false when in its least determined direction
  // the lines carry less information than the prior (a vanishing point near infinity, a
  // nearly collinear triple), so it stays at the prior. When held (given, or
  // EstimateOptions::principalSigma = 0) the sigma is 0 and principalFromPrior true.
  Vec2 principalSigmaPx{0, 0};
  bool principalFromPrior = true;
  std::array<Vec2, 4> backWallPx;     // TL, TR, BR, BL; may lie outside the photo
  double layoutScore = 0;             // in [0, 1]: share of the box the photo supports
  std::vector<LineSegment> segments;  // photo pixels, with families and residuals
  std::vector<std::string> warnings;  // plain sentences (English, not translated)
  EstimateTimings timings;
  std::vector<SearchProgress> progress;
  double workingScale = 1;  // working image size / photo size
  // Opaque, shared between copies: the photo's brightness gradient at the layout's scale (at
  // most 400 px, about 1 MB), so correctEstimate re-searches the box with the same evidence
  // without the photo. Null for estimateCameraFromSegments.
  std::shared_ptr<const detail::PhotoEdges> photoEdges;
};

// Defaults are what `inlay-cli estimate` uses.
struct EstimateOptions {
  // Prior focal length in photo pixels (EXIF: ExifInfo::focalPx). nullopt: a 60 degree
  // horizontal field of view, held loosely. Never taken as truth (to hold a focal length, use
  // EstimateCorrection::lockedFocalPx).
  std::optional<double> priorFocalPx;
  // Log-space 1-sigma of the prior: 0.15 for EXIF (crops, zoom, wrong tags), 0.6 without.
  double priorLogSigmaExif = 0.15;
  double priorLogSigmaDefault = 0.6;
  // Hypotheses per focal-length rung (15 rungs: f from 0.25 to 6 times the long side, and the
  // prior). Below about 60 the search starts to miss (York: 1.43 deg median worst-direction error
  // at 5, 1.02-1.04 at 60-480); each doubling costs about 1-3 ms at 640 x 480.
  int searchIterations = 120;
  // Long side of the working image: larger photos are area-averaged down first.
  int maxWorkingSidePx = 800;
  // Segments kept (the longest ones) for the search; refinement uses the same.
  int maxSegments = 300;
  // Inlier threshold: angle between a segment and the line from its midpoint to the VP.
  double inlierAngleDeg = 2.0;
  // Principal point: > 0 refines it with the focal length and rotation under a Gaussian prior
  // at the image centre, 1-sigma this fraction of half the long side. The posterior follows the
  // geometry by itself: three finite, spread vanishing points place it (their orthocentre), a
  // point at infinity leaves it undetermined along the horizon, where the prior then holds it
  // (CameraEstimate::principalSigmaPx, principalFromPrior). Default 0 (held at the centre),
  // chosen held-out on York (tests/bench/bench_camera_principal.py, alternate halves A and B):
  // the strength best on A (0.16) scores B's horizon AUC 0.906 against 0.910 held; best on B is
  // 0 (A: 0.916). Even the truth's principal point (17 px off-centre) lifts the AUC only to
  // 0.915 with our detected lines; 0.04 improves York's median worst-direction error (0.86 vs
  // 1.00 deg) but the rendered rooms, whose point is centred, get worse (bench_camera). With the
  // sub-pixel segments (seed 1): 0.04 and 0.1 tie the held point's 0.919, 0.2 scores 0.914.
  double principalSigma = 0;
  // A known principal point (photo pixels; the scene file's camera.principal_px, a calibration):
  // held exactly, principalSigma ignored.
  std::optional<Vec2> principalPx;
  double cameraHeightM = 1.6;  // Camera::heightM of the result (the scene's camera.height_m)
  bool estimateLayout = true;
  // Refuse an implausible automatic box and search again (modeling/src/camera/layout_rules.h: a
  // floor crease too near the horizon for its depth, a room narrower than half the camera's
  // height, a ceiling the photo shows more than 3 camera heights up); a warning says what was
  // refused and what replaced it. Off: the best-supported box, whatever it is (a diagnosis).
  bool refuseImplausibleBox = true;
  uint32_t seed = 1;                    // hypothesis sampling; same seed, same result
  const CancelToken* cancel = nullptr;  // polled between stages and inside the loops
};

// linearRgb: H x W x C (C = 1, 3 or 4; alpha ignored), linear, the photo as loaded.
// Errors: an empty image or an unsupported channel count (key "photo"), cancellation
// (key "estimate", reason "cancelled").
Expected<CameraEstimate> estimateCamera(const ImageF& linearRgb, const EstimateOptions& options = {});

// The same from given segments (photo pixels; their `family` is ignored): for tests, for the
// benchmark on ground-truth segments, and for callers with their own line detector.
Expected<CameraEstimate> estimateCameraFromSegments(int widthPx, int heightPx,
                                                    const std::vector<LineSegment>& segments,
                                                    const EstimateOptions& options = {});

// What the user fixed. Anything not given is re-estimated from the previous estimate's
// segments; everything given is kept.
struct EstimateCorrection {
  // A camera the user fixed entirely (e.g. the scene file's camera.vanishing_points_px through
  // cameraFromVanishingPoints): kept exactly as given, principal point included; the segments
  // are re-assigned to its vanishing points and the back wall re-searched for it. The lines and
  // focal length below are then ignored.
  std::optional<Camera> fixedCamera;
  std::optional<double> lockedFocalPx;  // the focal length, held exactly
  // Per world axis (x, y, z): two user line segments {a0, b0, a1, b1} whose lines meet at that
  // axis's vanishing point (parallel lines: a vanishing point at infinity). Weighted far above
  // detected segments.
  std::array<std::optional<std::array<Vec2, 4>>, 3> vanishingLinesPx;
  // Back-wall corners the user placed (TL, TR, BR, BL), photo pixels; kept exactly. A back-wall
  // edge with both corners placed also acts as a user line of its family (top/bottom: x,
  // left/right: y), so four placed corners fix the x and y vanishing points.
  std::array<std::optional<Vec2>, 4> backWallCornersPx;
};

// The consistent camera and room after the user's fixes: camera re-fitted with the fixes as
// constraints (segments re-assigned), then the free back-wall lines re-searched: locally from
// the previous ones when the camera moved little (a drag does not make the box jump), globally
// when it turned more than 2 degrees or its focal length changed by more than 5%.
// `previous` must come from estimateCamera*/correctEstimate of the same photo; no image needed
// (it carries its segments), so it is cheap enough for every drag step (a few ms).
// Errors (key "correction..."): non-finite input, a focal length <= 0, two user lines of one
// axis that coincide, a fixed camera of another photo size or without a rotation, corners that
// cannot be a back wall for the re-fitted camera.
Expected<CameraEstimate> correctEstimate(const CameraEstimate& previous,
                                         const EstimateCorrection& correction,
                                         const EstimateOptions& options = {});

}  // namespace inlay
