// CPU mipmap levels of linear 8-bit data (see mipmaps.hpp): a 2x2 box filter with a bilinear
// filter's rounding.
#include "t10/mipmaps.hpp"

#include <algorithm>

namespace t10 {

Image8 nextMipLevel(const Image8& level) {
    const int width = std::max(1, level.width / 2);
    const int height = std::max(1, level.height / 2);
    Image8 next(width, height, level.channels);
    for (int y = 0; y < height; ++y) {
        const int y0 = std::min(2 * y, level.height - 1);
        const int y1 = std::min(2 * y + 1, level.height - 1);
        for (int x = 0; x < width; ++x) {
            const int x0 = std::min(2 * x, level.width - 1);
            const int x1 = std::min(2 * x + 1, level.width - 1);
            for (int c = 0; c < level.channels; ++c) {
                const int row0 = (level.at(x0, y0, c) + level.at(x1, y0, c) + 1) >> 1;
                const int row1 = (level.at(x0, y1, c) + level.at(x1, y1, c) + 1) >> 1;
                next.at(x, y, c) = static_cast<std::uint8_t>((row0 + row1 + 1) >> 1);
            }
        }
    }
    return next;
}

} // namespace t10
