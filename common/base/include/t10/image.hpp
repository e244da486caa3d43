// In-memory images shared by the loaders, writers, tests and tools.
// Row 0 is the BOTTOM row (OpenGL's order); the PNG/EXR/PFM writers and readers convert.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace t10 {

template <typename T>
struct ImageT {
    int width = 0;
    int height = 0;
    int channels = 0; // 1 grey, 3 RGB, 4 RGBA
    std::vector<T> data; // width * height * channels, bottom row first, channels interleaved

    ImageT() = default;
    ImageT(int w, int h, int c) : width(w), height(h), channels(c),
        data(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(c)) {}
    T& at(int x, int y, int c) { return data[(static_cast<std::size_t>(y) * width + x) * channels + c]; }
    const T& at(int x, int y, int c) const { return data[(static_cast<std::size_t>(y) * width + x) * channels + c]; }
    bool empty() const { return data.empty(); }
};

using Image8 = ImageT<std::uint8_t>;
using ImageF = ImageT<float>;

} // namespace t10
