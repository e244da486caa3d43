// Mipmap levels of linear 8-bit images made on the CPU, so that every driver samples the same texels
// and no renderer compiles a blit shader per texture format (on llvmpipe, glGenerateMipmap's first
// call for a format costs tens of milliseconds of shader compiling, in every process).
#pragma once
#include "t10/image.hpp"

namespace t10 {

// The level below `level`: each side halved (rounded down, never below 1), each texel the mean of the
// 2x2 block above it, rounded the way a bilinear filter at the block's centre rounds: each row's
// pair, then the two rows, each half up (llvmpipe's glGenerateMipmap, bit for bit). The last column
// or row of an odd side, and a side of 1, are not averaged past the edge. For linear data only:
// sRGB colour must be averaged in linear light.
Image8 nextMipLevel(const Image8& level);

} // namespace t10
