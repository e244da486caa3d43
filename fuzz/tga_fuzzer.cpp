// libFuzzer target: the TGA loader (decodeTga) on arbitrary bytes. A decoded image must be
// consistent with its size; an error must name the input. Sanitizers catch the rest.
#include "t10/tga.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const t10::TgaResult result = t10::decodeTga(data, size, "fuzz.tga");
    if (result.ok()) {
        const t10::Image8& image = result.image;
        const bool channelsOk = image.channels == 1 || image.channels == 3 || image.channels == 4;
        const bool sizeOk = image.width >= 1 && image.height >= 1 && image.width <= t10::kTgaMaxSide &&
                            image.height <= t10::kTgaMaxSide;
        if (!channelsOk || !sizeOk ||
            image.data.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                     static_cast<std::size_t>(image.channels))
            __builtin_trap();
    } else if (result.error.rfind("fuzz.tga: ", 0) != 0) {
        __builtin_trap(); // every message starts with the file's name
    }
    return 0;
}
