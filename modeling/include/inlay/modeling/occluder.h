// Occluders: a real object in the photo that must hide inserted objects standing behind it.
//
// The user scribbles strokes inside the object (foreground) and outside it (background). A
// graph cut (OpenCV grabCut, initialised with the strokes as definite foreground/background)
// segments the object; a soft alpha matte (OpenCV alphamat's information-flow matting) is then
// pulled in a band around the segmentation's edge. The matte stands in the room as a vertical
// card facing the camera, at the floor depth of the matte's lowest point, spanning the matte's
// bounding box; the renderer's rays pass through the card with probability 1 - alpha.
// OpenCV stays inside modeling; these functions are pure (no shared state), any thread may call
// them.
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image.h"

#include <array>
#include <string>
#include <vector>

namespace inlay {

struct MatteOptions {
  int strokeRadiusPx = 2;     // strokes are rasterised this thick (radius, pixels); default 2
  int grabCutIterations = 3;  // graph-cut / colour-model rounds; default 3
  int bandPx = 3;             // half-width of the trimap's unknown band around the cut; default 3
  // The work is confined to the scribbles' bounding box grown by this fraction of its size on
  // each side (at least 16 px); outside it is background. Default 0.25.
  double marginFraction = 0.25;
  // Strokes drawn across gaps in the object (between table legs) must not force the gap in. A
  // foreground-stroke pixel within this RGB distance (8-bit sRGB units) of a colour on the
  // background strokes is only "probably foreground"; one whose distance to the background's
  // colours is well below (2 x, plus this) its distance to the colours at its own stroke's ends
  // (strokes start and end on the object) is a background seed. Default 12.
  int ambiguousColourDistance = 12;
  // The pixel sizes above (stroke radius, band, margins) are pixels of a photo whose long side
  // is this long. A larger photo is matted at that scale: the scribbles' region (their box with
  // a 10 % margin) is cut from it, reduced by referenceLongSidePx / its long side, matted, and
  // the alpha brought back to the photo's pixels by joint bilateral upsampling guided by the
  // photo. So a photo and the same photo upscaled give the same matte (a 3 MP copy of d6 kept
  // the floor between the table's legs and made its 4 cm top a 22 cm slab). 0: every photo at
  // its own size. Default 640 (the dev rooms and York photos are matted at their own size).
  int referenceLongSidePx = 640;
};

struct OccluderMatte {
  ImageF alphaPx;              // H x W x 1, coverage in [0, 1], the photo's pixel frame
  std::array<int, 4> boxPx{};  // x0, y0, x1, y1 (exclusive) of alpha > 0.02
  Vec2 lowestPx{0, 0};         // the matte's lowest point (where it stands on the floor)
  double segmentSeconds = 0;   // grabCut
  double matteSeconds = 0;     // trimap + alphamat
};

// Matte from scribbles on the photo (linear RGB, H x W x 3, the photo's units). Strokes are
// polylines in pixels (a one-point stroke is a dot). Errors name `keyForMessages` (e.g.
// "occluders[0]") with ".foreground_scribbles_px" / ".background_scribbles_px": no stroke, no
// stroke inside the photo, strokes covering the whole photo (nothing left for the other side),
// or a segmentation that keeps no foreground.
Expected<OccluderMatte> matteFromScribbles(const ImageF& photoLinearRgb,
                                           const std::vector<std::vector<Vec2>>& foregroundPx,
                                           const std::vector<std::vector<Vec2>>& backgroundPx,
                                           const std::string& keyForMessages,
                                           const MatteOptions& options = {});

// The card: a vertical quad facing the camera (its normal the camera's horizontal viewing
// direction, reversed) through the floor point under the matte's lowest point, its corners the
// rays through the corners of the matte's box; kind OccluderCard, named "occluder_<group>_card",
// carrying the matte (Surface::cardAlpha). Errors: the lowest point at or above the horizon, a
// camera looking straight down, a box corner whose ray misses the card's plane.
Expected<Surface> occluderCard(const Camera& camera, const OccluderMatte& matte, int groupIndex,
                               const std::string& keyForMessages);

// What an occluder's matte says about an extrusion built down to the floor (a table top drawn
// without a thickness): below each top edge the camera sees, the matte is followed straight
// down (in the world, 2 mm steps) from just under the edge to the floor. Where the matte covers
// the edge and then gives way (floor or wall seen under the top: the user's own segmentation of
// the object says it is open there), the covered band is the slab's thickness at that sample;
// where it covers all the way down to the bottom tenth (a leg, a cabinet's front) the sample
// is solid. The top is judged open when the matte covers the edge at >= `minSamples` samples
// and at least `openShare` of them give way; then the thickness is their median. Pure; any
// thread.
struct SlabEvidence {
  int coveredSamples = 0;  // samples whose top edge the matte covers (alpha >= 0.5)
  int openSamples = 0;     // of those, where the matte gives way before the floor
  bool open = false;       // the rule's verdict: build a slab, not a solid
  double thicknessM = 0;   // the median covered band under the edge, when open
};
struct SlabOptions {
  int minSamples = 12;     // default 12: a few pixels of edge are no evidence
  double openShare = 0.5;  // default 0.5: most of the visible front is open
};
SlabEvidence slabFromMatte(const Camera& camera, const Extrusion& extrusion, const ImageF& alphaPx,
                           const SlabOptions& options = {});

}  // namespace inlay
