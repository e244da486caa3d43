// The --input HDR image as a stage renders it: read within the GL context's limits and the memory
// the machine has, refused with the limit's name when it does not fit, and free of NaN and infinity.
#pragma once
#include "t10/image_io.hpp"

#include <cstdint>
#include <iosfwd>
#include <string>

namespace t10 {

// Bytes one framebuffer pixel costs at most: reading (half RGBA + float RGBA) plus the stage's
// targets (RGBA16F accumulation, depth, the luminance and bloom chains, blur, default framebuffer,
// readback), rounded up. An estimate, so an image that cannot fit is refused before it is read.
constexpr std::uint64_t kRenderBytesPerPixel = 64;

// The limits of the current GL context (GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE,
// GL_MAX_VIEWPORT_DIMS: the smallest wins) and of the memory available now (MemAvailable).
ExrLimits renderLimits();

// Reads `path` for rendering: beyond renderLimits() or with a side below
// contract::kMinFramebufferSide it throws t10::Error naming the file and the limit. +infinity becomes kHalfMax, NaN and -infinity 0, with
// one warning on `warnings` that counts the pixels, unless `keepNonFinite`.
ImageF loadInputImage(const std::string& path, bool keepNonFinite, std::ostream& warnings);

} // namespace t10
