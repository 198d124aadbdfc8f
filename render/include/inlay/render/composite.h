// Debevec's differential composite, in linear photo units:
//   I = M * I_obj + (1 - M) * (I_b + I_obj - I_noobj)
// photoLinear (I_b), withObjects (I_obj), withoutObjects (I_noobj): W x H x 3; mask (M): W x H x 1
// in [0,1]. Where withObjects == withoutObjects and mask == 0 the result is bit-identical to the
// photo. Negative results are clamped to 0; nothing non-finite is produced.
//
// `unclipped` (optional, W x H x >= 3): the room's radiance where the photo clips it (the light
// model's, ProjectedAlbedo::photoRadiance: a sunlit patch many times the clip level); it marks the
// clipped pixels (above the photo in some channel). Where the objects change such a pixel, I_b
// is the larger of the photo and I_noobj, channel by channel: an object's shadow on a clipped
// patch is then I_obj (the render's own shadow) instead of clip + I_obj - I_noobj, which goes far
// below zero in the clipped channels and leaves a black or coloured hole. Untouched pixels stay
// the photo bit for bit.
#pragma once

#include "inlay/modeling/image.h"

namespace inlay {

ImageF differentialComposite(const ImageF& photoLinear, const ImageF& withObjects,
                             const ImageF& withoutObjects, const ImageF& mask,
                             const ImageF* unclipped = nullptr);

// Multiply by 2^stops (exposure) in place.
void applyExposure(ImageF& linear, double stops);

}  // namespace inlay
