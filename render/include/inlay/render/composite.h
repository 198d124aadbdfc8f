// Debevec's differential composite, in linear photo units:
//   I = M * I_obj + (1 - M) * (I_b + I_obj - I_noobj)
// photoLinear (I_b), withObjects (I_obj), withoutObjects (I_noobj): W x H x 3; mask (M): W x H x 1
// in [0,1]. Where withObjects == withoutObjects and mask == 0 the result is bit-identical to the
// photo. Negative results are clamped to 0; nothing non-finite is produced.
#pragma once

#include "inlay/modeling/image.h"

namespace inlay {

ImageF differentialComposite(const ImageF& photoLinear, const ImageF& withObjects,
                             const ImageF& withoutObjects, const ImageF& mask);

// Multiply by 2^stops (exposure) in place.
void applyExposure(ImageF& linear, double stops);

}  // namespace inlay
