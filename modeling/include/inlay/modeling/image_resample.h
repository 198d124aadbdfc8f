// Working sizes and edge-aware upsampling for stages that work on a reduced copy of the photo
// (the engine's preparation: camera, lighting and decomposition on about a megapixel, the
// render and composite at the photo's own size).
#pragma once

#include "inlay/modeling/image.h"

#include <array>
#include <vector>

namespace inlay {

// The size of a `width` x `height` image scaled (aspect kept, rounded down) to at most
// `maxPixels` pixels; the size itself when it has no more, or when `maxPixels` <= 0.
std::array<int, 2> workingSizeFor(int width, int height, double maxPixels);

// Joint bilateral upsampling (Kopf, Cohen, Lischinski, Uyttendaele, SIGGRAPH 2007) with the
// photo as the guide: `low` (w x h x C) was computed from `lowGuide` (w x h, the area average of
// `fullGuide`, W x H). Each full-size pixel averages the low pixels within `radius` of it,
// weighted by their distance (Gaussian, `sigmaSpatial` low pixels) and by how far the guide's
// value there is from its own (Gaussian on the log of the guide, `sigmaRange`): values do not
// leak across the photo's edges, so an edge falls where the full photo has it.
// With `ratio`, what is upsampled is each channel's ratio to the guide's matching channel, and
// the result is that ratio times the full guide: where `low` is the photo times a smooth factor
// (an albedo is the photo over a smooth shading, the direct light the photo times its share)
// the result keeps the photo's full-size detail, which no upsampling of `low` itself can
// recover. Low pixels whose guide is darker than `darkGuide` (no ratio to speak of) give their
// own value instead. The guide's channels are matched to `low`'s when their counts agree, else
// its mean is used. A pixel whose result is not finite takes the spatial average of `low`. An empty input
// or a `fullGuide` no larger than `lowGuide` returns `low` resized (resizeImage's rules).
struct JointBilateralOptions {
  int radius = 1;             // low pixels (1: the 2 x 2 around the pixel)
  double sigmaSpatial = 1.0;  // low pixels
  double sigmaRange = 0.25;   // natural log of the guide
  bool ratio = false;
  double darkGuide = 2e-3;  // linear guide value
};
ImageF jointBilateralUpsample(const ImageF& low, const ImageF& lowGuide, const ImageF& fullGuide,
                              const JointBilateralOptions& options = {});
// The same for several images of the guide's low size at once (the weights, which depend on the
// guide only, are found once per pixel). Each must be lowGuide's size; fullGuide larger.
std::vector<ImageF> jointBilateralUpsample(const std::vector<const ImageF*>& lows,
                                           const ImageF& lowGuide, const ImageF& fullGuide,
                                           const JointBilateralOptions& options = {});

}  // namespace inlay
