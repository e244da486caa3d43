// What the image file formats of image_io.cpp and exr_io.cpp share (a private header of
// common/content): the largest side they read, the error naming the file, the check of an image
// before it is written. Qualified names (image_file::fail): the unity build may put these files in one
// batch with others that have a fail() of their own.
#pragma once
#include "t10/error.hpp"
#include "t10/image.hpp"

#include <cstddef>
#include <string>

namespace t10::image_file {

// The largest side accepted when reading EXR or PFM: far beyond any render here, small enough that
// width * height * channels cannot overflow. The GL context's own limit (ExrLimits) is lower.
constexpr long long kMaxReadSide = 65536;

[[noreturn]] inline void fail(const std::string& path, const std::string& fault) { throw Error(path + ": " + fault); }

template <typename T>
void checkImage(const std::string& path, const ImageT<T>& image, bool allowGrey) {
    const bool channelsOk = image.channels == 3 || image.channels == 4 || (allowGrey && image.channels == 1);
    if (image.width <= 0 || image.height <= 0 || !channelsOk)
        fail(path, "cannot write a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                       " image with " + std::to_string(image.channels) + " channels");
    const std::size_t expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                 static_cast<std::size_t>(image.channels);
    if (image.data.size() != expected)
        fail(path, "image data holds " + std::to_string(image.data.size()) + " values, expected " +
                       std::to_string(expected));
}

} // namespace t10::image_file
