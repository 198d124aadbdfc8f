// Sun shafts from the user's two boxes: one around the lit patch(es), one around their source
// (a window). Inside the patch box the lit pixels are separated from the unlit ones (a
// threshold on log luminance between the two modes, Otsu's), giving a soft mask on the surface
// the patch lies on; the light's direction runs from the source's lit pixels to the patch's,
// both as area-weighted 3D centroids on the room. With only one box the user gives the
// direction. The result is a masked directional light whose strength the lighting fit finds.
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image.h"
#include "inlay/modeling/scene_file.h"
#include "inlay/render/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace inlay {

struct ShaftEstimate {
  SunLight sun;      // strength (irradianceOverPi) not yet fitted: (1, 1, 1)
  ImageF litMaskPx;  // = sun.litMask: W x H x 1 soft mask of the lit patch (or window)
  Vec3 patchCentroidWorld{0, 0, 0};
  Vec3 sourceCentroidWorld{0, 0, 0};
  bool directionGiven = false;
  double contrast = 0;  // mean lit / mean unlit luminance inside the patch box
  int litPixels = 0;
};

// photoLinear: W x H x 3. Errors name `key` (e.g. "shafts[0].shaft_box_px") and the reason: a
// box outside the photo, no lit patch found (too little contrast), no direction.
Expected<ShaftEstimate> sunFromShaft(const ShaftKeys& shaft, const ImageF& photoLinear,
                                     const Camera& camera, const SceneGeometry& geometry,
                                     const std::string& key);

// The wall thickness a window of a sun's beam is assumed to have when the photo does not show it
// (PrepareOptions::windowRevealDepthM): 0.2 m, an outer wall's, chosen on the dev sun room d4
// (docs/generalization.md, "The unseen window's reveal").
inline constexpr double kWindowRevealDepthM = 0.2;

// The fewest lit pixels on one box surface from which openingOfBeam places an opening.
inline constexpr int kMinBeamPixels = 50;

// The opening a sun's beam came through, as far as its lit patch shows it. Sunlight enters
// through a window that lets the sky in as well; when the photo does not show that window, its
// sky is a light no outline marks, and the room's light would be short by it. Every lit pixel
// of the beam's mask (> 0.5) is carried back against the light to the box surface (a wall or
// the ceiling) it crosses; the rectangle spanning the 2nd to 98th percentiles of those points
// in that surface's plane, 1 mm into the room, is the opening.
struct BeamOpening {
  AreaLight light;   // facing into the room, radiance (1, 1, 1): the lighting fit finds it
  int surface = -1;  // the box surface it lies on
  double widthM = 0, heightM = 0;
  double visibleShare = 0;  // of 8 x 8 points on it, the share the camera sees
  int pixels = 0;           // lit pixels carried back onto it
};

// Nullopt when fewer than `minPixels` lit pixels reach one box surface (the beam's mask empty,
// or the lit points blocked by a table top). The patch is cut where the photo ends, and so is
// the opening.
// A window lies in a wall of some thickness: the beam that reaches the room is what passes both
// the wall's outer and inner openings, so its section in the inner plane is the window cut on the
// side the light comes from (a high sun: the window's top part lights the reveal, not the room).
// The sky comes in through the whole inner opening. `revealDepthM` > 0: the rectangle is widened
// by that cut, revealDepthM times the beam's slope across the wall (its in-plane part over its
// part along the normal), on the side opposite the beam's in-plane shift, each side by at most
// the section's own extent and within the box; 0 (or not finite): the beam's section as it is.
std::optional<BeamOpening> openingOfBeam(const SunLight& sun, const Camera& camera,
                                         const SceneGeometry& geometry, int minPixels = kMinBeamPixels,
                                         double revealDepthM = 0);

namespace detail {
// Otsu's threshold between the two modes of `values` (OpenCV's, on 256 levels between their
// extremes) and the mean of the values on each side. Constant values: both means and the
// threshold are that value.
double otsuThreshold(const std::vector<double>& values, double* meanLow, double* meanHigh);
}  // namespace detail

}  // namespace inlay
