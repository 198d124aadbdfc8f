// The linear values an 8-bit photo read as sRGB holds (internal to modeling): loadImage decodes
// code k to srgbCodeTable8()[k], and redecodePhoto relies on it.
#pragma once

#include <array>

namespace inlay::detail {

const std::array<float, 256>& srgbCodeTable8();

}  // namespace inlay::detail
