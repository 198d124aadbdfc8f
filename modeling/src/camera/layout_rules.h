// When an automatic box is implausible for the camera that took the photo (internal to
// modeling; used by layout.cpp's search, free of OpenCV so tests can include it).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/line_segment.h"

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace inlay::detail {

// A box's size in metres as the room builder measures it (roomFromBackWall): the bottom corners'
// rays meet the floor (the camera stands heightM above it), the back wall's plane is their mean
// depth, the top corners' rays meet that plane at the ceiling. creaseRad: the angle below the
// horizon at which the camera sees the back wall's foot straight ahead (atan(heightM / depth)).
struct BoxSize {
  bool ok = false;  // false: a bottom corner at or above the horizon, or the wall behind
  double depthM = 0, widthM = 0, creaseRad = 0;
  double ceilingM = std::numeric_limits<double>::quiet_NaN();  // NaN: the top corners miss it
};
BoxSize boxSizeOf(const Camera& camera, const std::array<Vec2, 4>& cornersPx);

// When an automatic box is implausible for the camera (checked on the search's boxes; placed
// corners are the user's and never refused). Geometry, in units of the photo and of the
// camera's height above the floor:
//  - depth: the back wall's distance is h / tan(a), a the crease's angle below the horizon. The
//    horizon is known to horizonSigmaRad (the vertical vanishing point's 1-sigma) and a crease to
//    creaseSigmaPx; a box whose depth the photo cannot bound within depthFactor at 2 sigma
//    (tan(a + 2s) / tan(a - 2s) > depthFactor) is beyond what the photo can show at that height.
//  - ceiling: a ceiling crease the photo shows more than maxCeilingOverEye camera heights up.
//    The ceiling is h (1 + tan(above) / tan(below)) for the top and bottom edges' angles from the
//    horizon: a high ceiling over a floor crease means that floor crease lies near the horizon,
//    the top of furniture or a sill taken for the floor, which is what makes a box tens of
//    metres deep. The search then holds the top edge and looks for the floor crease lower down.
//  - width: a room narrower than minWidthOverEye camera heights cannot hold the photographer.
//  - extent: under a ceiling the photo shows, a room more than maxRoomOverEye camera heights
//    both deep and wide (a corridor is legitimately deep: York P1080033, 19 m by 7.9 m). A
//    lounge's or office's floor crease is mostly hidden behind furniture; the best-supported line
//    near the horizon is then a sill, a cabinet's base or a window's rail, the back wall lands
//    far away and the side wall out of view follows it (York P1040845: 14 m by 14 m under a
//    4.2 m ceiling). A box that replaces a refused one (`replacing`: the photo's best evidence
//    has misled once) must keep both sizes within the bound, else the search, which has no
//    evidence for the hidden crease, stops just inside it; it then looks for the floor crease
//    lower down, between the furniture. 6 (9.6 m at 1.6 m) was chosen on York half A (even
//    indices): its accepted indoor boxes are at most 4.9 camera heights in their smaller size;
//    at 8, P1040845's replacement was 14.1 m by 12.8 m, the bound's own size.
struct BoxRules {
  double horizonSigmaRad = 0;
  double creaseSigmaPx = 1;
  double depthFactor = 2;
  double maxCeilingOverEye = 3;
  double minWidthOverEye = 0.5;
  double maxRoomOverEye = 6;
};
// Which rule refuses a box (none: plausible) and why, as a sentence fragment with the box's
// metres. showsCeiling: the photo shows the top edge as a ceiling crease (else the ceiling rule
// does not apply: the top of a facade against the sky is no ceiling).
struct Implausible {
  enum Rule { kNone, kDepth, kWidth, kCeiling, kExtent } rule = kNone;
  std::string why;
  explicit operator bool() const { return rule != kNone; }
};
Implausible implausibility(const Camera& camera, const std::array<Vec2, 4>& cornersPx, bool showsCeiling,
                           const BoxRules& rules, bool replacing = false);

// Which horizontal (family 0) segments are the tops of furniture rather than a floor crease
// (issue #16, York round). Things stand on a floor crease: the vertical (family 1) edges that
// meet a crease end there from above (a door's frame, a cabinet against the wall, the wall's own
// corner). From a table's or a shelf's top, a sill or a counter, vertical edges hang down (legs,
// sides, a cabinet's front) and end lower, on the floor in front of the wall. A segment is a top
// when more length of vertical edges hangs from it than stands on it: an end of the vertical
// within tolPx of the segment, the vertical reaching at least tolPx further on its other side.
// Verticals that cross a segment (a pillar or a chair in front of the crease) count for
// neither, and so do verticals whose line passes within ambiguousPx of the forward vanishing
// point forwardPx (below it a tiled floor's receding lines look vertical: the checkered
// training rooms). Per segment; false for other families and for the user's lines.
std::vector<bool> furnitureTops(const std::vector<LineSegment>& segments, double tolPx,
                                const std::optional<Vec2>& forwardPx = std::nullopt,
                                double ambiguousPx = 0);

// A vertical (family 1) edge of the photo, its ends in photo pixels.
struct Upright {
  Vec2 upPx, downPx;  // its upper and lower end in the photo
};
// The vertical edges that may stand on a floor crease: family 1, not the user's, not skip[i] (a
// saturated patch's outline), and not along the forward vanishing point (as furnitureTops).
std::vector<Upright> uprightsOf(const std::vector<LineSegment>& segments, const std::vector<bool>& skip,
                                const std::optional<Vec2>& forwardPx, double ambiguousPx);
// How much vertical edge stands on the line through a and b (issue #16, York round 17b): the
// photo-pixel length of the uprights whose lower end lies within tolPx of the line, between a
// and b, and whose upper end lies more than tolPx above it (`down`: the photo's downward
// direction, across the line). Things stand on a floor crease: a door's frame, a cabinet's side,
// the wall's own corner end there, and nothing of them goes on below it. An upright that another
// continues below the line (its two ends within 1.5 tolPx of the upright's line, or its upper end
// within 2 tolPx of the upright's foot: a tiled wall's joint, a pillar found in two pieces, a
// frame and its reflection) crosses the line and does not count. Legs hanging from a
// top are not counted against it (furnitureTops does that for the top's own segment). 0 for a
// degenerate line or no uprights.
double standingOn(const std::vector<Upright>& uprights, const Vec2& a, const Vec2& b, const Vec2& down,
                  double tolPx);

// Whether a refused box (its score refusedTotal, of it refusedStanding from standingOn) led the
// box that replaced it only through the uprights standing on its floor crease: it leads, and not
// without them. A sill under a window's mullions (York P1080005's shop windows): the photo's edges
// and faces prefer the replacement, the refusal undid the cue's mistake, and the box kept is not
// in doubt for it. False for a non-finite score (the refusal then warns).
bool ledByStandingAlone(double refusedTotal, double refusedStanding, double nextTotal,
                        double nextStanding);

// What makes an automatic box doubtful, each a reason (empty: no doubt).
struct BoxDoubts {
  // The floor crease is in view but nothing in the photo marks it, or (floorOutOfView) lies below
  // the photo: the box shows no floor.
  std::string unseenCrease;
  bool floorOutOfView = false;
  // The best-supported box was refused as implausible: why, and what replaced it (empty when it led
  // only through the uprights standing on its crease: ledByStandingAlone).
  std::string refused;
};
// One sentence for CameraEstimate::warnings (issue #16, fifth York round): what to do in the
// studio first, then every reason: "check the room box: drag the back wall's <corners>, now at
// <where>, onto <which creases>; why: <reasons>". A refused box: all four corners (the photo's
// best evidence misled once); an unseen crease alone: the bottom two. cornersPx (TL, TR, BR, BL)
// in a W x H photo; a corner outside it is named so, a non-finite one "(undefined)". Empty
// without a doubt.
std::string boxAdvice(const BoxDoubts& doubts, const std::array<Vec2, 4>& cornersPx, double W, double H);

}  // namespace inlay::detail
