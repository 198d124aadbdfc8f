#pragma once
// The photo's 8-bit codes found once and handed to both the response's estimate and the
// re-decode (response.h finds them in each; at 12 MP that is 0.1 s of CPU each time).
#include "inlay/modeling/response.h"

#include <vector>

namespace inlay {

// estimateResponse(img, options) with `codes` = srgbCodesOf(img) already found.
ResponseEstimate estimateResponseFromCodes(const ImageF& srgbDecodedRgb,
                                           const std::vector<unsigned char>& codes,
                                           const ResponseEstimateOptions& options = {});

// redecodePhoto(img, 8, response) with `codes` = srgbCodesOf(img) already found: every value
// becomes response.table8()[its code]. An image that is not W x H x 3 or codes of another
// size are decoded as redecodePhoto does.
void redecodePhotoFromCodes(ImageF& srgbDecodedRgb, const std::vector<unsigned char>& codes,
                            const CameraResponse& response);

}  // namespace inlay
