// A sun's strength from the photo's lit and shadowed pixels of the same surface.
//
// Inside the beam a pixel shows B = rho (S e + g), outside it B = rho g, where e is the sun's
// unit irradiance / pi there (beam mask x cosine), g the rest of its light (the gathered light
// plus the area lights' direct light) and rho the albedo, which the ratio cancels: the lit
// patch and a band of the same surface beside it (same rows, so the same depth and texture
// scale) hold the same materials, so the q-quantile of B / (S e + g) over the lit pixels equals
// the q-quantile of B / g over the shadowed ones. S is solved per channel and quantile by
// bisection and the median over the quantiles kept (0.4, 0.6, 0.8 and 1 times the usable
// range: its upper part, since noise widens the shadow's spread and biases its lowest ranks). A clipped lit pixel ranks above every
// unclipped one (its true value is only bounded below), so only quantiles below the lit
// pixels' unclipped share are used: a patch the photo clips still tells S from its darker
// materials (grout, texture), where the decomposition's albedo is least trustworthy. What it
// does not cancel: an error of g's scale (S goes with it) and a surface of one flat colour whose
// patch clips everywhere (refused: the estimate's strength stays).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image.h"
#include "inlay/render/scene.h"

#include <array>
#include <string>
#include <vector>

namespace inlay {

struct SunRatioOptions {
  double saturatedAbove = 0.98;  // linear value treated as clipped
  int minPixels = 150;           // lit and shadowed pixels each, at least
  int erodePx = 3;               // lit pixels keep this far from the beam's edge
  int shadowGapPx = 15;          // shadowed pixels keep this far from the beam
  double clippedShareUse = 0.7;  // quantiles up to this share of the lit pixels' unclipped share
  int lightSamples = 8;          // points per area light for g
};

struct SunRatioResult {
  Vec3 strength = Vec3::Zero();  // RGB irradianceOverPi
  int litPixels = 0, shadowPixels = 0;
  Vec3 quantilesUsed = Vec3::Zero();  // per channel, how many quantiles voted
};

// `photoLinear` and `gathered`: W x H x 3 in the photo's frame; `lights` with their radiances.
// Errors (key "suns"): mismatched images, too few lit or shadowed pixels, a channel whose lit
// pixels are all clipped.
Expected<SunRatioResult> sunStrengthFromShadowRatio(const ImageF& photoLinear, const Camera& camera,
                                                    const SceneGeometry& geometry,
                                                    const ImageF& gathered,
                                                    const std::vector<AreaLight>& lights,
                                                    const SunLight& sun,
                                                    const SunRatioOptions& options = {});

// A sun's strength from the light its clipped patch bounces onto the rest of the room.
//
// When the patch clips everywhere the ratio above has nothing to compare and the photo gives
// only a lower bound: rho_p (S e + o) >= the clip level on the patch (rho_p: its surface's
// albedo). What the patch bounces, S times b (`bounce`: the estimate's gathered irradiance / pi
// per unit strength, straight and by way of the surfaces the camera does not see), reaches room
// the photo shows unclipped, where B = rho_s (o + S b), o the light that does not scale with the
// sun (the gathered light less the bounce at the strengths it holds, plus the area lights'
// direct light). One factor t scales the given strength (its colour kept: the clipped patch
// tells none): on a logarithmic grid, the t that makes each surface's albedo B / (o + t S b)
// flattest (the mean |log albedo - its surface's median|, robust to texture, summed over the
// channels) among the t the photo allows in every channel: the patch clipped (rho_p the median
// albedo of its surface outside the beam at that t: the albedo split stays consistent; the
// bounce scales with rho_p) and no surface's median albedo above 1. The strength is left as
// given (raised to the lower bound) when the bounce cannot tell: its share of those pixels'
// light is small (another light swamps it), the cost falls to the grid's end, or it is as low
// over a wide range (`determined` false, `warning` says why). Chosen on the dev sun room d4
// (docs/generalization.md, "The sun's strength from the light its clipped patch bounces").
struct SunBounceOptions {
  double saturatedAbove = 0.98;     // linear value treated as clipped
  int minPixels = 150;              // bounce pixels (and the patch's clipped pixels), at least
  int maxPixels = 6000;             // bounce pixels and patch pixels sampled, at most
  int minSurfacePixels = 40;        // a surface with fewer bounce pixels is left out of the cost
  int beamGapPx = 15;               // bounce pixels keep this far from the beam
  double lowerBoundQuantile = 0.5;  // of the patch pixels' bounds (robust to its soft edge)
  // The bounce's share of the light on the bounce pixels at the best factor (the channels'
  // mean): below it, another light swamps the bounce and the strength is not determined.
  double minBounceShare = 0.05;
  // Determined: the factors whose cost is within flatTolerance of the best's span at most
  // maxSpread (largest over smallest), and the best is not the grid's last allowed point.
  double flatTolerance = 0.01;
  double maxSpread = 4;
  // The grid spans [b / 4, b x maxFactor] times the given strength, b the lower bound's largest
  // factor over it (1 when nothing bounds it).
  double maxFactor = 64;
  int steps = 121;       // grid points
  int lightSamples = 8;  // points per area light for o
  uint32_t seed = 7;
};

// A sun's bounce as the lighting estimate gathered it (LightingEstimate::sunBounce,
// sunBounceUnseen and sunBounceUnseenAt of that sun): W x H x 3 each, irradiance / pi per unit
// strength; `gathered` holds `direct` at the sun's strength and `unseen` at `unseenAt`.
struct SunBounceImages {
  ImageF direct;  // straight from the clipped patch (and the sunlit surfaces the camera misses)
  ImageF unseen;  // by way of the surfaces the camera does not see, bounced there; may be empty
  Vec3 unseenAt = Vec3::Zero();
};

struct SunBounceResult {
  // RGB irradianceOverPi: the estimate's colour times the fitted factor (when not determined,
  // the estimate's, raised to the lower bound).
  Vec3 strength = Vec3::Zero();
  Vec3 lowerBound = Vec3::Zero();  // the clipped patch's bound, per channel
  double bounceShare = 0;          // the bounce's share of the bounce pixels' light (channels' mean)
  // The span (largest over smallest factor) of the factors whose cost is within flatTolerance of
  // the best's.
  double spread = 0;
  bool determined = false;
  int bouncePixels = 0, patchPixels = 0;
  std::string warning;  // why the bounce does not determine the strength (empty when it does)
};

// `photoLinear`, `gathered` and `bounce`: W x H x 3 in the photo's frame; `sun` with the
// strength the gathered light holds its direct bounce at. Errors (key "suns"): mismatched images, no
// lit pixel, too few bounce pixels or clipped patch pixels, a patch surface not seen outside
// the beam.
Expected<SunBounceResult> sunStrengthFromBounce(const ImageF& photoLinear, const Camera& camera,
                                                const SceneGeometry& geometry, const ImageF& gathered,
                                                const SunBounceImages& bounce,
                                                const std::vector<AreaLight>& lights,
                                                const SunLight& sun,
                                                const SunBounceOptions& options = {});

}  // namespace inlay
