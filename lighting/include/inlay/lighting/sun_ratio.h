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

}  // namespace inlay
